import org.kheperasim.api.*;

/** Does not compile: a missing semicolon and an unknown method. */
public class Broken extends Controller {
    @Override
    protected void doWork() {
        setSpeeds(3, 3)
        sleepMillis(100);
    }
}
