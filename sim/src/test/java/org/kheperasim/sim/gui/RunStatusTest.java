package org.kheperasim.sim.gui;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * What the window tells about a run, in a real window under Xvfb ({@link RunStatusDriver}, in a
 * child JVM): run's score at a paused moment and at the end of a {@code lab} run, which ends at the
 * arena's time limit as {@code run}'s does; a status bar that follows the run and turns red on an
 * exception; a refusal's reason in the console; the palette's keys from the console; Help by titles,
 * closed with Esc; Open .java's filter. Skipped without Xvfb, except in CI.
 */
class RunStatusTest {
    @Test
    @Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theWindowScoresEndsAndReportsARunAsRunDoes() throws Exception {
        WindowDriverRun.run("the run status test", RunStatusDriver.class, null, 210, new String[] {"SCORE AT PAUSE OK",
            "TIME LIMIT OK", "EXCEPTION STATUS OK", "REFUSAL OK", "PALETTE KEYS OK", "HELP OK", "OPEN JAVA FILTER OK"});
    }
}
