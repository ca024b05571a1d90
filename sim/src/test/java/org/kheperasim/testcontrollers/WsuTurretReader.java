package org.kheperasim.testcontrollers;

import edu.wsu.KheperaSimulator.RobotController;

/** A WSU KSuite 1.1.2 controller that steers by the K213 turret (readLvtImage, the pixel intensities). */
public class WsuTurretReader extends RobotController {
    public WsuTurretReader() {
    }

    @Override
    public void doWork() throws Exception {
        float[] image = readLvtImage();
        float left = 0;
        float right = 0;
        for (int i = 0; i < image.length; i++) {
            if (i < image.length / 2) {
                left += image[i];
            } else {
                right += image[i];
            }
        }
        float max = getPixelMaxIntensity();
        if (max > 250) {
            setMotorSpeeds(left > right ? 2 : 5, left > right ? 5 : 2);
        } else {
            setMotorSpeeds(4, 4);
        }
        sleep(40);
    }

    @Override
    public void close() throws Exception {
    }
}
