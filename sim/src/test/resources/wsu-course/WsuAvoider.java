import edu.wsu.KheperaSimulator.RobotController;

/** A reactive avoider, as the course's first assignment had it. */
public class WsuAvoider extends RobotController {
    public WsuAvoider() {
    }

    public void doWork() throws Exception {
        if (getDistanceValue(1) > 400 || getDistanceValue(2) > 400 || getDistanceValue(3) > 400) {
            setMotorSpeeds(3, -3);
        } else if (getDistanceValue(4) > 400) {
            setMotorSpeeds(-3, 3);
        } else {
            setMotorSpeeds(5, 5);
        }
        sleep(50);
    }

    public void close() throws Exception {
        setMotorSpeeds(0, 0);
    }
}
