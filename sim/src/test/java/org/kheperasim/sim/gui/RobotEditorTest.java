package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The robot editor in the window (Robot > Edit robot, Open robot file, New robot), under Xvfb in
 * one child JVM ({@link RobotEditorDriver}): a drag turns a sensor and moves another, the sheet
 * refuses a bad wheel base and takes a good one, the saved file reads back with those numbers, Try
 * in arena restarts the run with the edited robot, and robots from scratch (a file, and one
 * designed in the editor) run Braitenberg in the arena, and a 3-sensor robot designed in the editor is
 * refused by name to Braitenberg and runs a controller written for any robot. Screenshots under {@code target/robot-editor/}.
 */
class RobotEditorTest {
    @Test
    @Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theRobotEditorEditsSavesAndTriesARobot() throws Exception {
        WindowDriverRun.requireXvfb("the robot editor test");
        Path scratch = Path.of("src/test/resources/robots/roundbot.yaml").toAbsolutePath();
        WindowDriverRun.run("the robot editor test", RobotEditorDriver.class, "1366x900x24", 280,
                new String[] {"ROBOT EDITOR OK"}, scratch.toString(),
                Path.of("src/test/java/org/kheperasim/sim/run/AnyRobotAvoider.java").toAbsolutePath().toString());
        Path dir = WindowDriverRun.target().resolve("robot-editor");
        for (String png : new String[] {"editor-1-khepera1.png", "editor-3-edited.png", "window-1-tried.png",
            "window-2-scratch-file.png", "window-5-tri-runs.png"}) {
            assertTrue(Files.size(dir.resolve(png)) > 10_000, png + " was saved");
        }
    }
}
