package org.kheperasim.sim.run;

import org.kheperasim.api.Controller;
import org.kheperasim.api.Sensor;

/**
 * For tests: an obstacle avoider for any robot, written against the sensors' mounts rather than the
 * Khepera's indices: each sensor pushes the robot to turn away by the sine of its heading.
 */
public class AnyRobotAvoider extends Controller {
    @Override
    protected void doWork() {
        double turn = 0;
        double ahead = 0;
        for (Sensor s : sensors()) {
            double h = StrictMath.toRadians(s.getMount().headingDeg());
            turn += s.getDistValue() * StrictMath.sin(h) / 100.0;
            ahead = StrictMath.max(ahead, StrictMath.cos(h) > 0.9 ? s.getDistValue() : 0);
        }
        int cruise = ahead > 500 ? 0 : 6;
        int spin = ahead > 500 ? 4 : 0;
        int left = (int) StrictMath.max(-15, StrictMath.min(15, StrictMath.round(cruise + turn + spin)));
        int right = (int) StrictMath.max(-15, StrictMath.min(15, StrictMath.round(cruise - turn - spin)));
        setSpeeds(left, right);
        sleepMillis(100);
    }
}
