package student;

import org.kheperasim.api.Controller;

/** Drives straight ahead at 40 mm/s, whatever it meets: into a wall, a cap or another robot. */
public class Straight extends Controller {
    @Override
    protected void doWork() {
        setSpeeds(5, 5);
        sleepMillis(100);
    }
}
