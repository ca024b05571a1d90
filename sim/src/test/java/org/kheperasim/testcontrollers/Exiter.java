package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.Motor;

/** Drives for a while, then ends the whole program with System.exit(3), as a careless student's code may. */
public class Exiter extends Thread {
    private final Motor motor;

    public Exiter(CurrentRobotState state, MessagePasser mp) {
        motor = state.getMotorState();
    }

    @Override
    public void run() {
        motor.setMotorSpeeds(3, 3);
        try {
            Thread.sleep(20_000);
        } catch (InterruptedException e) {
            return;
        }
        System.exit(3);
    }
}
