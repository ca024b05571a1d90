package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.Motor;

/** Drives forward for a second, then divides by zero. */
public class Thrower extends Thread {
    private final Motor motor;

    public Thrower(CurrentRobotState state, MessagePasser mp) {
        motor = state.getMotorState();
    }

    @Override
    public void run() {
        motor.setMotorSpeeds(5, 5);
        try {
            Thread.sleep(1000);
        } catch (InterruptedException e) {
            return;
        }
        int zero = motor.getLeftSpeed() - 5;
        System.out.println(10 / zero);   // the student's mistake, on line 24
    }
}
