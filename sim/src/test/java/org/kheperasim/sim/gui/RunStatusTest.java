package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * What the window tells about a run, in a real window under Xvfb ({@link RunStatusDriver}, in a
 * child JVM): run's score at a paused moment and at the end of a {@code lab} run, which ends at the
 * arena's time limit as {@code run}'s does; a status bar that follows the run and turns red on an
 * exception; a refusal's reason in the console; the palette's keys from the console; Help by titles,
 * closed with Esc; Open .java's filter; no JDK log line about preferences on a first launch. Skipped
 * without Xvfb, except in CI.
 */
class RunStatusTest {
    @Test
    @Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theWindowScoresEndsAndReportsARunAsRunDoes() throws Exception {
        // A first launch: no preferences yet (the JDK logged a line about creating their folder).
        Path prefs = GuiEndToEndTest.home(RunStatusDriver.class.getName()).resolve(".java");
        if (Files.exists(prefs)) {
            try (var files = Files.walk(prefs)) {
                files.sorted(java.util.Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
            }
        }
        String log = WindowDriverRun.run("the run status test", RunStatusDriver.class, null, 210, new String[] {
            "SCORE AT PAUSE OK", "TIME LIMIT OK", "EXCEPTION STATUS OK", "REFUSAL OK", "PALETTE KEYS OK", "HELP OK",
            "OPEN JAVA FILTER OK"});
        assertTrue(Files.exists(prefs), "the window kept its preferences");
        assertFalse(log.contains("preferences"), "a first launch logs nothing about preferences:\n" + log);
    }
}
