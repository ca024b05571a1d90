package org.kheperasim.link.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/** Drives and returns from run() with the wheels still turning. */
public class Returner extends Thread {
    private final CurrentRobotState robot;
    private final MessagePasser messages;

    public Returner(CurrentRobotState robot, MessagePasser messages) {
        this.robot = robot;
        this.messages = messages;
    }

    @Override
    public void run() {
        robot.getMotorState().setMotorSpeeds(7, 7);
        messages.sendMessage("driving at 7");
        try {
            Thread.sleep(300);
        } catch (InterruptedException e) {
            return;
        }
    }
}
