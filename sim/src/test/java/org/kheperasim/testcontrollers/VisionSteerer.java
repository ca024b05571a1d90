package org.kheperasim.testcontrollers;

import org.kheperasim.api.Controller;
import org.kheperasim.api.IrSensor;

/**
 * An honest, deterministic controller that reads its vision turret every step: it turns towards the
 * brightest part of its image and away from walls, and sleeps 30 ms between decisions.
 */
public class VisionSteerer extends Controller {
    @Override
    protected void doWork() {
        int[] image = vision().getImage();
        int sum = 0;
        int weight = 0;
        for (int i = 0; i < image.length; i++) {
            sum += i * image[i];
            weight += image[i];
        }
        int turn = weight == 0 ? 0 : (int) Math.round((sum / (double) weight - 31.5) / 8);
        if (proximity(IrSensor.FRONT_LEFT) > 600 || proximity(IrSensor.FRONT_RIGHT) > 600) {
            setSpeeds(-3, 3);
        } else {
            setSpeeds(4 + turn, 4 - turn);
        }
        sleepMillis(30);
    }
}
