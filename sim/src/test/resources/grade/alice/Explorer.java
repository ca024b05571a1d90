import org.kheperasim.api.*;

/** Drives ahead and turns away from what is near: the quick start's first controller. */
public class Explorer extends Controller {
    @Override
    protected void doWork() {
        int left = Math.max(proximity(IrSensor.LEFT_45), proximity(IrSensor.FRONT_LEFT));
        int right = Math.max(proximity(IrSensor.RIGHT_45), proximity(IrSensor.FRONT_RIGHT));
        if (left > 500 || right > 500) {
            setSpeeds(left >= right ? 3 : -3, left >= right ? -3 : 3);
        } else if (proximity(IrSensor.LEFT_90) > 700) {
            setSpeeds(5, 2);
        } else if (proximity(IrSensor.RIGHT_90) > 700) {
            setSpeeds(2, 5);
        } else {
            setSpeeds(5, 5);
        }
        sleepMillis(100);
    }
}
