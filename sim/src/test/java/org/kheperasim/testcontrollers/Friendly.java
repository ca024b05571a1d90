package org.kheperasim.testcontrollers;

import org.kheperasim.api.Controller;
import org.kheperasim.api.IrSensor;

/** The friendlier base class: no constructor, a doWork() loop, sleepMillis on the simulation clock. */
public class Friendly extends Controller {
    private int steps;

    @Override
    protected void setup() {
        print("setup at " + System.currentTimeMillis() % 100_000);
    }

    @Override
    protected void doWork() {
        setSpeeds(2, 2);
        proximity(IrSensor.FRONT_LEFT);
        sleepMillis(250);
        if (++steps == 8) {
            print("steps " + steps + " at " + System.nanoTime());
            killControl();
        }
    }
}
