package org.kheperasim.sim.run;

import org.kheperasim.api.Controller;

/** For tests: drives straight ahead at the Braitenberg's cruising speed in the robot's units, whatever it meets. */
public class DriveStraight extends Controller {
    @Override
    protected void doWork() {
        setSpeeds(6, 6);
        sleepMillis(100);
    }
}
