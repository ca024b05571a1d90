package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.testfixtures.Cli;

/**
 * {@code gui --robot-file}, as {@code run}'s: the window's robots are that robot unless their arena line
 * names one (under Xvfb, {@link GuiRobotFileDriver}), and a wrong robot file is said before any window opens.
 */
class GuiRobotFileTest {
    @Test
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theWindowsRobotsAreTheRobotFilesUnlessTheirLineNamesOne() throws Exception {
        WindowDriverRun.run("the gui --robot-file test", GuiRobotFileDriver.class, null, 150,
                new String[] {"window robots: epuck khepera2", "run robots: epuck khepera2", "ROBOT FILE OK"});
    }

    @Test
    void aWrongRobotFileIsSaidBeforeAnyWindow() {
        Cli.Printed p = Cli.main("gui", "--arena", "lab", "--robot-file", "no-such-robot.yaml");
        assertEquals(2, p.code(), p.out() + p.err());
        assertTrue(p.err().contains("no-such-robot.yaml"), p.err());
    }
}
