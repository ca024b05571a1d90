package org.kheperasim.link.testcontrollers;

import org.kheperasim.api.Controller;

/** A Controller subclass (no constructor) asking for more than the clamp allows, and using the gripper. */
public class Fast extends Controller {
    @Override
    protected void setup() {
        gripper().lowerArm();
        gripper().closeGripper();
    }

    @Override
    protected void doWork() {
        setSpeeds(100, -100);
        sleepMillis(20);
    }
}
