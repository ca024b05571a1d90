import org.kheperasim.api.*;

/** The Appendix's shape: a Thread with (CurrentRobotState, MessagePasser), using a helper class. */
public class Robot extends Thread {
    private final CurrentRobotState state;
    private volatile boolean active = true;

    public Robot(CurrentRobotState state, MessagePasser mp) {
        this.state = state;
    }

    public void killControl() {
        active = false;
    }

    @Override
    public void run() {
        Sensor[] sensors = state.getSensorValues();
        Motor motor = state.getMotorState();
        while (active) {
            int[] speeds = Turns.away(sensors[2].getDistValue(), sensors[3].getDistValue());
            motor.setMotorSpeeds(speeds[0], speeds[1]);
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                return;
            }
        }
    }
}
