package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.cli.Main;

/**
 * File > Export run as web page, in a real window under Xvfb ({@link WebExportDriver}, in a child
 * JVM): the page of a live run paused at 20 s (its title, its length, the window's score), of a run
 * whose controller threw (the student's line), and of a replayed trace (the page {@code replay --html}
 * writes, byte for byte). Skipped without Xvfb, except in CI.
 */
class WebExportTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theWindowExportsTheRunShownAsAWebPage() throws Exception {
        WindowDriverRun.requireXvfb("the web export test");
        Path trace = dir.resolve("maze.trace");
        assertEquals(0, Main.commandLine().execute("run", "--arena", "maze", "--controller", "WallFollower", "--seed", "3",
                "--seconds", "10", "--trace", trace.toString(), "--quiet"));
        WindowDriverRun.run("the web export test", WebExportDriver.class, null, 150,
                new String[] {"LIVE EXPORT OK", "FAILURE EXPORT OK", "REPLAY EXPORT OK"}, trace.toString());
        assertTrue(Files.size(WindowDriverRun.target().resolve("export-live.html")) > 20_000, "the page was kept");
    }
}
