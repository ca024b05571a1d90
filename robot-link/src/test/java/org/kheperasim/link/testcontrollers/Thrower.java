package org.kheperasim.link.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/** Drives, then throws. */
public class Thrower extends Thread {
    private final CurrentRobotState robot;

    public Thrower(CurrentRobotState robot, MessagePasser messages) {
        this.robot = robot;
    }

    @Override
    public void run() {
        robot.getMotorState().setMotorSpeeds(6, 6);
        try {
            Thread.sleep(300);
        } catch (InterruptedException e) {
            return;
        }
        throw new IllegalStateException("student bug");
    }
}
