package org.kheperasim.testcontrollers;

import org.kheperasim.api.StepController;

/** Divides by zero in its tenth step, after printing the time. */
public class StepThrower extends StepController {
    private int steps;

    @Override
    protected void step() {
        setSpeeds(5, 5);
        if (++steps == 10) {
            print("tenth step at " + System.currentTimeMillis() % 100000);
            int zero = steps - 10;
            print("never " + 1 / zero);
        }
    }
}
