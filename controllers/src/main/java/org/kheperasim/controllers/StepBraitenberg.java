package org.kheperasim.controllers;

import org.kheperasim.api.IrSensor;
import org.kheperasim.api.StepController;

/**
 * {@link Braitenberg} as a step controller: the same weighted sums, called once every 100 ms instead
 * of looping in a thread of its own. A step controller runs on the robot by default (on-board: it
 * reads the latest scan and its speeds act at once); through the serial link
 * ({@code controller.mode=tethered}) it drives the same path as {@link Braitenberg}. For swarms: a
 * step costs no thread hand-over.
 *
 * <p>Its numbers can be handed to it ({@code evaluate}'s {@code parameters}, for an evolutionary
 * algorithm): {@code weights} (six numbers, sensors 0..5) and {@code cruise} (a speed, units).
 */
public class StepBraitenberg extends StepController {
    /** Cruising speed, units (about 48 mm/s). */
    private static final int CRUISE = 6;
    /** How strongly each of sensors 0..5 (left 90° to right 90°) pushes the robot to turn right. */
    private static final double[] TURN_WEIGHTS = {0.4, 0.8, 1.2, -1.2, -0.8, -0.4};
    /** Proximity at which the front counts as blocked. */
    private static final int BLOCKED = 500;

    /** This robot's weights and speed: the constants above unless its run hands it others (set up in setup()). */
    private double[] weights;
    private double cruise;

    @Override
    protected void setup() {
        // A copy of the constant: one definition of this class serves every robot (docs/controller-rules.md).
        weights = parameters().vector("weights", TURN_WEIGHTS.clone());
        cruise = parameters().get("cruise", CRUISE);
        if (weights.length != TURN_WEIGHTS.length) {
            throw new IllegalArgumentException("parameter weights has " + weights.length + " numbers: give "
                    + TURN_WEIGHTS.length + ", for sensors 0..5");
        }
    }

    @Override
    protected void step() {
        int frontLeft = proximity(IrSensor.FRONT_LEFT);
        int frontRight = proximity(IrSensor.FRONT_RIGHT);
        double turn = 0;
        for (int i = 0; i < weights.length; i++) {
            turn += weights[i] * sensors()[i].getDistValue() / 100.0;
        }
        if (StrictMath.max(frontLeft, frontRight) > BLOCKED) {
            // Spin away from the nearer side; with nothing to tell them apart, turn right.
            setSpeeds(turn >= 0 ? 4 : -4, turn >= 0 ? -4 : 4);
        } else {
            setSpeeds(clamp((int) StrictMath.round(cruise + turn)), clamp((int) StrictMath.round(cruise - turn)));
        }
    }

    private static int clamp(int speed) {
        return StrictMath.max(-15, StrictMath.min(15, speed));
    }
}
