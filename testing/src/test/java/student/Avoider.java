package student;

import org.kheperasim.api.Controller;
import org.kheperasim.api.IrSensor;

/** The README's first controller: drives ahead and turns away from what its front sensors see. */
public class Avoider extends Controller {
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
