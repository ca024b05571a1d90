import edu.wsu.KheperaSimulator.RobotController;

/**
 * Sets a 100 ms pause in its constructor (which the simulator overrides with 20 ms, as the original
 * did), and asks for speeds outside -9..9 (ignored, as the original did).
 */
public class WsuSlow extends RobotController {
    private int steps;

    public WsuSlow() {
        setWaitTime(100);
    }

    public void doWork() throws Exception {
        steps++;
        if (steps == 1) {
            setMotorSpeeds(12, 4); // left ignored: the left wheel stays at 0
        } else if (steps == 2) {
            setMotorSpeeds(-20, 30); // both ignored
        } else if (steps == 51) {
            System.out.println("step 51 at " + System.currentTimeMillis() % 100000);
            setFinished(true);
        }
    }

    public void close() throws Exception {
        setMotorSpeeds(0, 0);
    }
}
