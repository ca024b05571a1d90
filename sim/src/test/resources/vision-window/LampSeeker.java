import org.kheperasim.api.*;

/** Turns on the spot until its vision turret sees the brightest light near the middle of its image. */
public class LampSeeker extends Controller {
    @Override
    protected void doWork() {
        int p = vision().getBrightestPixel();
        if (p < 28) {
            setSpeeds(-2, 2);
        } else if (p > 36) {
            setSpeeds(2, -2);
        } else {
            setSpeeds(3, 3);
        }
        sleepMillis(100);
    }
}
