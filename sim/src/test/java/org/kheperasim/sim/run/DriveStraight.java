package org.kheperasim.sim.run;

import org.kheperasim.api.Controller;

/**
 * For tests: drives straight ahead at the Braitenberg's cruising speed, 48 mm/s in the robot's own units
 * (6 on a Khepera, 373 steps/s on an e-puck), whatever it meets.
 */
public class DriveStraight extends Controller {
    private static final double CRUISE_MM_S = 48;

    @Override
    protected void doWork() {
        int speed = (int) StrictMath.round(CRUISE_MM_S / motor().getMmPerSecondPerUnit());
        setSpeeds(speed, speed);
        sleepMillis(100);
    }
}
