import edu.wsu.KheperaSimulator.RobotController;
import util.Smoother;

/** Steers from smoothed sensors, with a helper class in its own package beside it. */
public class WsuHelped extends RobotController {
    private final Smoother left = new Smoother(4);
    private final Smoother right = new Smoother(4);

    public WsuHelped() {
    }

    public void doWork() throws Exception {
        int l = left.add(Math.max(getDistanceValue(1), getDistanceValue(2)));
        int r = right.add(Math.max(getDistanceValue(3), getDistanceValue(4)));
        if (l > 300 || r > 300) {
            setMotorSpeeds(l > r ? 3 : -3, l > r ? -3 : 3);
        } else {
            setMotorSpeeds(6, 6);
        }
    }

    public void close() throws Exception {
        setMotorSpeeds(0, 0);
    }
}
