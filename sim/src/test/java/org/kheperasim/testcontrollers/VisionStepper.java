package org.kheperasim.testcontrollers;

import org.kheperasim.api.IrSensor;
import org.kheperasim.api.StepController;

/** A step controller (on the robot's processor) that steers by its vision turret's brightest pixel and grips what it meets. */
public class VisionStepper extends StepController {
    @Override
    protected void step() {
        int p = robot().getVisionTurret().getBrightestPixel();
        int d = robot().getVisionTurret().getDarkestPixel();
        if (proximity(IrSensor.FRONT_LEFT) > 700 || proximity(IrSensor.FRONT_RIGHT) > 700) {
            setSpeeds(3, -3);
        } else {
            setSpeeds(p < d ? 2 : 4, p < d ? 4 : 2);
        }
        if (robot().getGripper().isObjectPresent()) {
            robot().getGripper().closeGripper();
        }
    }
}
