package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/** Creeps forward at 1 unit and lowers the gripper's arm: its fingers come down beside whatever is there. */
public class CreepLowering extends Thread {
    private final CurrentRobotState state;

    public CreepLowering(CurrentRobotState state, MessagePasser mp) {
        this.state = state;
    }

    @Override
    public void run() {
        state.getMotorState().setMotorSpeeds(1, 1);
        state.getGripper().lowerArm();
        while (true) {
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                return;
            }
        }
    }
}
