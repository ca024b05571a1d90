package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.Motor;

/** Drives for two seconds, then loops forever without touching the API. */
public class Spinner extends Thread {
    private final Motor motor;
    public static volatile long counter;

    public Spinner(CurrentRobotState state, MessagePasser mp) {
        motor = state.getMotorState();
    }

    @Override
    public void run() {
        motor.setMotorSpeeds(4, 4);
        try {
            Thread.sleep(2000);
        } catch (InterruptedException e) {
            return;
        }
        while (true) {
            counter++;
        }
    }
}
