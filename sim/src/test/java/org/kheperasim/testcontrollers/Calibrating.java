package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/**
 * Calibrates in a static initializer: it reads the front sensor and sleeps twenty times there
 * (simulated time passes, the other robots run), then drives. A virtual thread that waits inside
 * a class initializer holds its carrier thread meanwhile, so several of these must not leave the
 * other robots' threads without one.
 */
public class Calibrating extends Thread {
    static CurrentRobotState robot;

    static final class Calibration {
        static final int FRONT;

        static {
            int sum = 0;
            for (int i = 0; i < 20; i++) {
                sum += robot.getSensorValues()[2].getDistValue();
                try {
                    Thread.sleep(50);
                } catch (InterruptedException e) {
                    break;
                }
            }
            FRONT = sum / 20;
        }
    }

    private final CurrentRobotState state;
    private final MessagePasser mp;

    public Calibrating(CurrentRobotState state, MessagePasser mp) {
        this.state = state;
        this.mp = mp;
    }

    @Override
    public void run() {
        robot = state;
        mp.sendMessage("calibrated " + (Calibration.FRONT >= 0));
        state.getMotorState().setMotorSpeeds(3, 3);
        try {
            Thread.sleep(60_000);
        } catch (InterruptedException e) {
            // stopped
        }
    }
}
