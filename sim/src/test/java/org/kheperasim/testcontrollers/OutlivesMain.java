package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/** Starts a thread that drives forever, and returns after one second: the thread ends with it. */
public class OutlivesMain extends Thread {
    private final CurrentRobotState state;

    public OutlivesMain(CurrentRobotState state, MessagePasser mp) {
        this.state = state;
    }

    @Override
    public void run() {
        new Thread(() -> {
            while (true) {
                state.getMotorState().setMotorSpeeds(2, 2);
                try {
                    Thread.sleep(10);
                } catch (InterruptedException e) {
                    // ignored: it keeps driving
                }
            }
        }, "driver").start();
        try {
            Thread.sleep(1000);
        } catch (InterruptedException e) {
            return;
        }
    }
}
