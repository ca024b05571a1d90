package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/** Two threads take two locks in opposite orders, sleeping between: a deadlock at 10 ms. */
public class Deadlock extends Thread {
    private final CurrentRobotState state;
    private final Object a = new Object();
    private final Object b = new Object();

    public Deadlock(CurrentRobotState state, MessagePasser mp) {
        this.state = state;
    }

    @Override
    public void run() {
        state.getMotorState().setMotorSpeeds(4, 4);
        new Thread(() -> take(b, a), "second").start();
        take(a, b);
    }

    private void take(Object first, Object second) {
        synchronized (first) {
            try {
                Thread.sleep(10);
            } catch (InterruptedException e) {
                return;
            }
            synchronized (second) {
                state.getMotorState().setMotorSpeeds(0, 0);
            }
        }
    }
}
