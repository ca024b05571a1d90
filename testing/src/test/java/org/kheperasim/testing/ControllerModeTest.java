package org.kheperasim.testing;

import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** A test chooses where the controller runs: on the robot, or through the serial link. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ControllerModeTest {

    @Test
    void onBoardAndTetheredAreTheRunsTheTraceHeaderNames() {
        Run tethered = Run.of("Braitenberg").in("lab").seconds(10).seed(2).run();
        Run onBoard = Run.of("Braitenberg").in("lab").seconds(10).seed(2).onBoard().run();
        Run stepTethered = Run.of("StepBraitenberg").in("lab").seconds(10).seed(2).tethered().run();
        assertTrue(tethered.trace().contains("\n# mode tethered\n"), "a thread-style controller is tethered by default");
        assertTrue(onBoard.trace().contains("\n# mode onboard\n"), "onBoard() puts it on the robot");
        assertTrue(stepTethered.trace().contains("\n# mode tethered\n"), "tethered() puts a step controller on the link");
        assertNotEquals(tethered.trace(), onBoard.trace(), "on the robot it sees fresher values, so it drives otherwise");
    }
}
