import org.kheperasim.api.*;

/** Calls System.exit after a second. */
public class Quitter extends Controller {
    @Override
    protected void doWork() {
        setSpeeds(4, 4);
        sleepMillis(1000);
        System.exit(3);
    }
}
