package org.kheperasim.controllers;

import org.kheperasim.api.IrSensor;
import org.kheperasim.api.StepController;

/**
 * A swarm behaviour as a step controller: robots gather into clusters. With nothing seen a robot
 * wanders (a slow curve that changes side now and then); when its front sensors see something it
 * turns towards the stronger side and creeps up to it; once something is close ahead it stops and
 * stays, since a robot standing there is as good a neighbour as any. Walls hold robots too, as in
 * the simplest aggregation models; neighbours make clusters grow. One decision every 100 ms.
 */
public class Aggregation extends StepController {
    /** Proximity beyond which something is seen. */
    private static final int SEEN = 150;
    /** Proximity beyond which it is close enough to stay. */
    private static final int CLOSE = 700;
    private int steps;

    @Override
    protected void step() {
        steps++;
        int left = StrictMath.max(proximity(IrSensor.LEFT_45), proximity(IrSensor.FRONT_LEFT));
        int right = StrictMath.max(proximity(IrSensor.RIGHT_45), proximity(IrSensor.FRONT_RIGHT));
        int front = StrictMath.max(left, right);
        if (front > CLOSE) {
            stopMotors();
        } else if (front > SEEN) {
            // Turn towards the stronger side, and creep.
            setSpeeds(left > right ? 1 : 3, left > right ? 3 : 1);
        } else {
            // Wander: curve one way for 5 s, then the other.
            boolean leftward = (steps / 50) % 2 == 0;
            setSpeeds(leftward ? 4 : 6, leftward ? 6 : 4);
        }
    }
}
