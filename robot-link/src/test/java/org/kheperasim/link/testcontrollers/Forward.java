package org.kheperasim.link.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/** Drives forward at 5 and keeps saying so, until killed. */
public class Forward extends Thread {
    private final CurrentRobotState robot;
    private volatile boolean active = true;

    public Forward(CurrentRobotState robot, MessagePasser messages) {
        this.robot = robot;
    }

    public void killControl() {
        active = false;
    }

    @Override
    public void run() {
        while (active) {
            robot.getMotorState().setMotorSpeeds(5, 5);
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                return;
            }
        }
    }
}
