package org.kheperasim.testcontrollers;

import org.kheperasim.api.Controller;

/** Drives for a second, says "looping", then loops for ever without an API call (a careless student's busy wait). */
public class Looper extends Controller {
    private static volatile long spins;

    @Override
    protected void doWork() {
        setSpeeds(2, 2);
        sleepMillis(1000);
        print("looping");
        while (spins >= 0) {
            spins++;
        }
    }
}
