package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/**
 * Drives, then waits (no timeout) for a notify that its helper was to send; the helper ends
 * without sending it. Nothing can wake the controller again: a deadlock, once the helper has ended.
 */
public class AbandonedWaiter extends Thread {
    private final CurrentRobotState state;
    private final Object lock = new Object();

    public AbandonedWaiter(CurrentRobotState state, MessagePasser mp) {
        this.state = state;
    }

    @Override
    public void run() {
        state.getMotorState().setMotorSpeeds(3, 3);
        Thread helper = new Thread(() -> {
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "helper");
        helper.start();
        synchronized (lock) {
            try {
                lock.wait();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
