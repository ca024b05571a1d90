import edu.wsu.KheperaSimulator.RobotController;

/** A controller written for the WSU Khepera Simulator, unchanged. */
public class Avoider extends RobotController {
    public Avoider() {
    }

    @Override
    public void doWork() throws Exception {
        if (getDistanceValue(2) > 600 || getDistanceValue(3) > 600) {
            setMotorSpeeds(3, -3);
        } else {
            setMotorSpeeds(5, 5);
        }
    }

    @Override
    public void close() throws Exception {
        setMotorSpeeds(0, 0);
    }
}
