package org.kheperasim.controllers;

import org.kheperasim.api.IrSensor;
import org.kheperasim.api.StepController;

/**
 * {@link Braitenberg} as a step controller: the same weighted sums, called by the simulator once
 * every 100 ms instead of looping in a thread of its own. Both drive the robot along the same path:
 * a step comes one period after the previous step's last call, as {@code sleepMillis(100)} at the
 * end of {@code doWork()} does. For swarms: a step costs no thread hand-over.
 */
public class StepBraitenberg extends StepController {
    /** Cruising speed, units (about 48 mm/s). */
    private static final int CRUISE = 6;
    /** How strongly each of sensors 0..5 (left 90° to right 90°) pushes the robot to turn right. */
    private static final double[] TURN_WEIGHTS = {0.4, 0.8, 1.2, -1.2, -0.8, -0.4};
    /** Proximity at which the front counts as blocked. */
    private static final int BLOCKED = 500;

    @Override
    protected void step() {
        int frontLeft = proximity(IrSensor.FRONT_LEFT);
        int frontRight = proximity(IrSensor.FRONT_RIGHT);
        double turn = 0;
        for (int i = 0; i < TURN_WEIGHTS.length; i++) {
            turn += TURN_WEIGHTS[i] * sensors()[i].getDistValue() / 100.0;
        }
        if (StrictMath.max(frontLeft, frontRight) > BLOCKED) {
            // Spin away from the nearer side; with nothing to tell them apart, turn right.
            setSpeeds(turn >= 0 ? 4 : -4, turn >= 0 ? -4 : 4);
        } else {
            setSpeeds(clamp((int) StrictMath.round(CRUISE + turn)), clamp((int) StrictMath.round(CRUISE - turn)));
        }
    }

    private static int clamp(int speed) {
        return StrictMath.max(-15, StrictMath.min(15, speed));
    }
}
