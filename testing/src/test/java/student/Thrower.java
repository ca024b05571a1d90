package student;

import org.kheperasim.api.Controller;

/** Drives for 2 simulated seconds, then indexes past the end of an array. */
public class Thrower extends Controller {
    private final int[] readings = new int[2];
    private int loops;

    @Override
    protected void doWork() {
        setSpeeds(3, 3);
        sleepMillis(100);
        if (++loops == 20) {
            readings[loops] = 1; // throws here
        }
    }
}
