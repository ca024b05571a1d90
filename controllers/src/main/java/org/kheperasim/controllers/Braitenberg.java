package org.kheperasim.controllers;

import org.kheperasim.api.Controller;
import org.kheperasim.api.IrSensor;

/**
 * An obstacle avoider in the manner of Braitenberg's vehicles: each wheel is driven by a weighted
 * sum of the proximity sensors, so an obstacle on the left speeds up the left wheel and slows the
 * right one, turning the robot away. Something straight ahead makes it turn on the spot, towards
 * the freer side. One decision every 100 ms.
 */
public class Braitenberg extends Controller {
    /** Cruising speed, units (about 48 mm/s). */
    private static final int CRUISE = 6;
    /** How strongly each of sensors 0..5 (left 90° to right 90°) pushes the robot to turn right. */
    private static final double[] TURN_WEIGHTS = {0.4, 0.8, 1.2, -1.2, -0.8, -0.4};
    /** Proximity at which the front counts as blocked. */
    private static final int BLOCKED = 500;

    @Override
    protected void doWork() {
        int frontLeft = proximity(IrSensor.FRONT_LEFT);
        int frontRight = proximity(IrSensor.FRONT_RIGHT);
        double turn = 0;
        for (int i = 0; i < TURN_WEIGHTS.length; i++) {
            turn += TURN_WEIGHTS[i] * sensors()[i].getDistValue() / 100.0;
        }
        if (StrictMath.max(frontLeft, frontRight) > BLOCKED) {
            // Spin away from the nearer side; with nothing to tell them apart, turn right.
            if (turn >= 0) {
                setSpeeds(4, -4);
            } else {
                setSpeeds(-4, 4);
            }
        } else {
            int left = clamp((int) StrictMath.round(CRUISE + turn));
            int right = clamp((int) StrictMath.round(CRUISE - turn));
            setSpeeds(left, right);
        }
        sleepMillis(100);
    }

    private static int clamp(int speed) {
        return StrictMath.max(-15, StrictMath.min(15, speed));
    }
}
