package student;

import org.kheperasim.api.Controller;

/** After 1 simulated second, loops without ever calling the robot's API again. */
public class Looper extends Controller {
    private int loops;
    private volatile long spins;

    @Override
    protected void doWork() {
        sleepMillis(100);
        if (++loops == 10) {
            while (spins >= 0) {
                spins++;
            }
        }
    }
}
