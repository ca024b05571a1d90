package org.kheperasim.testcontrollers;

import org.kheperasim.api.StepController;

/** Breaks the step contract: it sleeps inside step(). */
public class StepSleeper extends StepController {
    @Override
    protected void step() {
        setSpeeds(3, 3);
        try {
            Thread.sleep(50);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
