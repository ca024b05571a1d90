package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/** Drives straight ahead at 5 units and keeps doing so. */
public class Straight extends Thread {
    private final CurrentRobotState state;

    public Straight(CurrentRobotState state, MessagePasser mp) {
        this.state = state;
    }

    @Override
    public void run() {
        state.getMotorState().setMotorSpeeds(5, 5);
        while (true) {
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                return;
            }
        }
    }
}
