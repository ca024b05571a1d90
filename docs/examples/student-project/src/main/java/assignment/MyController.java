package assignment;

import org.kheperasim.api.Controller;
import org.kheperasim.api.IrSensor;

/**
 * Your controller: drive along the corridor to the goal at its far end, and never touch a wall.
 *
 * <p>Ten times a second it reads its sensors: with something close ahead it turns on the spot, away
 * from it; close to a wall on one side it veers away; otherwise it drives ahead at {@link #SPEED}.
 */
public class MyController extends Controller {
    /** Wheel speed when the way ahead is clear, in Khepera speed units (one unit is about 8 mm/s). */
    static final int SPEED = 2;

    @Override
    protected void doWork() {
        int left = Math.max(proximity(IrSensor.LEFT_45), proximity(IrSensor.FRONT_LEFT));
        int right = Math.max(proximity(IrSensor.RIGHT_45), proximity(IrSensor.FRONT_RIGHT));
        if (left > 500 || right > 500) {
            // Something close ahead: turn on the spot, away from the nearer side.
            setSpeeds(left >= right ? 3 : -3, left >= right ? -3 : 3);
        } else if (proximity(IrSensor.LEFT_90) > 700) {
            setSpeeds(SPEED, SPEED / 2);         // close to a wall on the left: veer right
        } else if (proximity(IrSensor.RIGHT_90) > 700) {
            setSpeeds(SPEED / 2, SPEED);         // close to a wall on the right: veer left
        } else {
            setSpeeds(SPEED, SPEED);             // the way is clear: drive ahead
        }
        sleepMillis(100);
    }
}
