import edu.wsu.KheperaSimulator.KSGripperStates;
import edu.wsu.KheperaSimulator.RobotController;

/** Lowers the arm, opens, creeps to the cap ahead, closes on it and lifts it. */
public class WsuGripper extends RobotController {
    private int phase;

    public WsuGripper() {
    }

    public void doWork() throws Exception {
        if (phase == 0) {
            setArmState(KSGripperStates.ARM_DOWN);
            setGripperState(KSGripperStates.GRIP_OPEN);
            setMotorSpeeds(2, 2);
            phase = 1;
        } else if (phase == 1 && isObjectPresent()) {
            setMotorSpeeds(0, 0);
            setGripperState(KSGripperStates.GRIP_CLOSED);
            setArmState(KSGripperStates.ARM_UP);
            phase = 2;
        } else if (phase == 2 && getArmState() == KSGripperStates.ARM_UP) {
            System.out.println("holding " + isObjectHeld() + " arm up " + (getArmState() == KSGripperStates.ARM_UP)
                    + " gripper closed " + (getGripperState() == KSGripperStates.GRIP_CLOSED));
            setFinished(true);
        }
    }

    public void close() throws Exception {
    }
}
