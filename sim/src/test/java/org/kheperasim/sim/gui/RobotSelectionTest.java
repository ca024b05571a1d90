package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A run of two robots in the window: each drawn and labelled, and a click on the second makes the
 * sensor panel show it; then the window serves the arena, and two clients drive the robots into each other. Under Xvfb, in a child JVM ({@link RobotSelectionDriver}); screenshots
 * under {@code target/}. Skipped without Xvfb, except in CI.
 */
class RobotSelectionTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void clickingTheSecondRobotShowsItsSensors() throws Exception {
        WindowDriverRun.requireXvfb("the robot selection test");
        Path arena = dir.resolve("two.arena");
        Files.writeString(arena, "khepera-arena 1\nname two\nsize 1219.2 1219.2\nwall 0 4 1219.2 4 8\n"
                + "wall 0 1215.2 1219.2 1215.2 8\nwall 4 0 4 1219.2 8\nwall 1215.2 0 1215.2 1219.2 8\n"
                + "robot 300 600 0\nrobot 900 600 180\n");
        WindowDriverRun.run("the robot selection test", RobotSelectionDriver.class, null, 150,
                new String[] {"SELECTION OK", "PER-ROBOT CONTROLLER OK", "SERVE OK", "OTHER ARENA OK"}, arena.toString());
        assertTrue(Files.size(WindowDriverRun.target().resolve("robots-2-second-selected.png")) > 10_000,
                "a screenshot was saved");
    }
}
