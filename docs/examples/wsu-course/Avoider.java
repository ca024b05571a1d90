import edu.wsu.KheperaSimulator.RobotController;

/** Drives ahead, and turns right on the spot while something is close in front. */
public class Avoider extends RobotController {
    public Avoider() {
    }

    public void doWork() throws Exception {
        int front = 0;
        for (int i = 1; i <= 4; i++) {            // left 45°, front left, front right, right 45°
            front = Math.max(front, getDistanceValue(i));
        }
        if (front > 400) {
            setMotorSpeeds(3, -3);                // turn right on the spot
        } else {
            setMotorSpeeds(5, 5);                 // ahead at 5 units, about 40 mm/s
        }
    }

    public void close() throws Exception {
        setMotorSpeeds(0, 0);
    }
}
