package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
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
        Path xvfb = GuiEndToEndTest.xvfb();
        if (xvfb == null) {
            if ("true".equals(System.getenv("CI"))) {
                fail("Xvfb is not installed, and CI=true requires the window tests to run: apt-get install xvfb xauth");
            }
            Assumptions.assumeTrue(false, "Xvfb is not installed; the robot selection test needs it");
        }
        Path arena = dir.resolve("two.arena");
        Files.writeString(arena, "khepera-arena 1\nname two\nsize 1219.2 1219.2\nwall 0 4 1219.2 4 8\n"
                + "wall 0 1215.2 1219.2 1215.2 8\nwall 4 0 4 1219.2 8\nwall 1215.2 0 1215.2 1219.2 8\n"
                + "robot 300 600 0\nrobot 900 600 180\n");
        int[] display = new int[1];
        Process x = GuiEndToEndTest.startXvfb(xvfb, display);
        Path target = Path.of("target").toAbsolutePath();
        Files.createDirectories(target);
        Path log = target.resolve("robot-selection-driver.log");
        try {
            Process child = GuiEndToEndTest.childJvm(display[0], RobotSelectionDriver.class.getName(), log,
                    target.toString(), arena.toString());
            boolean done = child.waitFor(150, TimeUnit.SECONDS);
            if (!done) {
                child.destroyForcibly();
            }
            String out = Files.readString(log, StandardCharsets.UTF_8);
            assertTrue(done, "the driver did not finish in 150 s:\n" + out);
            assertEquals(0, child.exitValue(), out);
            assertTrue(out.contains("SELECTION OK"), out);
            assertTrue(out.contains("PER-ROBOT CONTROLLER OK"), out);
            assertTrue(out.contains("SERVE OK"), out);
            assertTrue(Files.size(target.resolve("robots-2-second-selected.png")) > 10_000, "a screenshot was saved");
            System.out.println(out);
        } finally {
            x.destroy();
            x.waitFor(5, TimeUnit.SECONDS);
        }
    }
}
