package org.kheperasim.testcontrollers;

import org.kheperasim.api.Controller;
import org.kheperasim.api.IrSensor;

/**
 * An honest, deterministic controller that now and then thinks hard: every seventh decision it
 * computes for some milliseconds of real time without a robot call. With a tiny hang timeout the
 * watchdog takes it off the run at a moment the wall clock decides (the test of real-time paths).
 */
public class Ponderer extends Controller {
    private long rounds;
    private long thought = 1;

    @Override
    protected void doWork() {
        int left = Math.max(proximity(IrSensor.LEFT_45), proximity(IrSensor.FRONT_LEFT));
        int right = Math.max(proximity(IrSensor.RIGHT_45), proximity(IrSensor.FRONT_RIGHT));
        if (left > 500 || right > 500) {
            setSpeeds(left >= right ? 3 : -3, left >= right ? -3 : 3);
        } else {
            setSpeeds(5, 4);
        }
        if (++rounds % 7 == 0) {
            for (int i = 0; i < 4_000_000; i++) {
                thought = thought * 6364136223846793005L + 1442695040888963407L;
            }
        }
        sleepMillis(thought == 0 ? 21 : 20);
    }
}
