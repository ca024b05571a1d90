import edu.wsu.KheperaSimulator.RobotController;

/** Turns on the spot by busy-waiting on the wheel counters with sleep(1), as students did, then stops itself. */
public class WsuCounterTurn extends RobotController {
    public WsuCounterTurn() {
    }

    public void doWork() throws Exception {
        long start = getRightWheelPosition();
        setMotorSpeeds(-3, 3);
        // A quarter turn: the wheels are 53 mm apart, so each travels 41.6 mm = 520 pulses.
        while (getRightWheelPosition() - start < 520) {
            Thread.sleep(1);
        }
        setMotorSpeeds(0, 0);
        System.out.println("turned at " + System.currentTimeMillis() % 100000);
        setFinished(true);
    }

    public void close() throws Exception {
    }
}
