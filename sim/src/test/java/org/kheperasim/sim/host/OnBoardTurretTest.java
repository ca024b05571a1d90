package org.kheperasim.sim.host;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.run.Simulation;

/**
 * A thread controller in {@code controller.mode=onboard} (and so under {@code profile=wsu}) runs on
 * the robot's processor: its turret image comes without the serial line's ≈ 60 ms, so a loop that
 * reads an image and pauses 20 ms runs about every 21 ms, as the original's did (23 ms), not every
 * ≈ 80 ms as through the link.
 */
class OnBoardTurretTest {
    private static int loops(Settings settings) {
        AtomicInteger lines = new AtomicInteger();
        Simulation.builder().arena("lab").controller("org.kheperasim.testcontrollers.WsuImageLoop").seed(1).seconds(2)
                .settings(settings).console(l -> {
                    if (l.text().startsWith("image 64")) {
                        lines.incrementAndGet();
                    }
                }).run();
        return lines.get();
    }

    @Test
    void onTheRobotAnImageTakesNoSerialTime() {
        int tethered = loops(Settings.defaults());
        int onboard = loops(Settings.defaults().with("controller.mode", "onboard"));
        int wsu = loops(Settings.defaults().with("profile", "wsu"));
        assertTrue(tethered <= 30, "through the link an image takes ~60 ms: " + tethered + " loops in 2 s");
        assertTrue(onboard >= 80, "on the robot a loop is the 20 ms pause and little more: " + onboard + " loops in 2 s");
        assertTrue(wsu >= 80, "the wsu profile runs on board: " + wsu + " loops in 2 s");
    }
}
