package student;

import org.kheperasim.api.Controller;

/** Calls System.exit after 2 simulated seconds: a rule of the simulator forbids it. */
public class Exiter extends Controller {
    private int loops;

    @Override
    protected void doWork() {
        sleepMillis(100);
        if (++loops == 20) {
            System.exit(3); // exits here
        }
    }
}
