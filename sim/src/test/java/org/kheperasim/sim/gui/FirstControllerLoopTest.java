package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.ReadmeSnippets;

/**
 * Getting started's loop in the window, as a newcomer goes round it: the README's MyFirst.java is
 * compiled by the window and run (F5); a mistake typed into it shows in the console with its line
 * after F10, and F5 then runs nothing (it ran the last version that compiled); a change of behaviour
 * is picked up by F10 and seen in the next run, and by Start alone after a Reset. Under Xvfb, in a
 * child JVM ({@link FirstControllerLoopDriver}); screenshots under {@code target/}. Skipped without
 * Xvfb, except in CI.
 */
class FirstControllerLoopTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void writeCompileRunRepeat() throws Exception {
        WindowDriverRun.requireXvfb("the first controller loop test");
        Path source = dir.resolve("MyFirst.java");
        Files.writeString(source, ReadmeSnippets.firstController());
        WindowDriverRun.run("the first controller loop test", FirstControllerLoopDriver.class, null, 200,
                new String[] {"RUN OK", "ERROR OK", "STALE REFUSED OK", "REPEAT OK", "START COMPILES OK"}, source.toString());
        assertTrue(Files.size(WindowDriverRun.target().resolve("first-1-running.png")) > 10_000, "a screenshot was saved");
    }
}
