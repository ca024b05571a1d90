import org.kheperasim.api.*;

/** Throws after two simulated seconds. */
public class Thrower extends Controller {
    private int steps;

    @Override
    protected void doWork() {
        setSpeeds(4, 4);
        sleepMillis(100);
        if (++steps == 20) {
            throw new IllegalStateException("frank's controller gave up at step " + steps);
        }
    }
}
