import org.kheperasim.api.*;

/** Drives for a second, then loops without ever calling the API again. */
public class Spinner extends Controller {
    public static volatile long counter;

    @Override
    protected void doWork() {
        setSpeeds(4, 4);
        sleepMillis(1000);
        while (true) {
            counter++;
        }
    }
}
