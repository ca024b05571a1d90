package org.kheperasim.testcontrollers;

import edu.wsu.KheperaSimulator.RobotController;

/** A WSU controller whose every loop reads one turret image (as the vision course's sensor manager does) and says so. */
public class WsuImageLoop extends RobotController {
    public WsuImageLoop() {
    }

    @Override
    public void doWork() throws Exception {
        float[] image = readLvtImage();
        System.out.println("image " + image.length);
    }

    @Override
    public void close() throws Exception {
    }
}
