package org.kheperasim.testcontrollers;

import org.kheperasim.api.StepController;

/** Never returns from its fifth step: a loop that waits for nothing. */
public class StepLooper extends StepController {
    private int steps;
    private long spins;

    @Override
    protected void step() {
        setSpeeds(3, 3);
        if (++steps == 5) {
            while (true) {
                spins++;
            }
        }
    }
}
