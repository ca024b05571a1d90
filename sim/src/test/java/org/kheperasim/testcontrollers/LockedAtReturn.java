package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/**
 * A sensor-manager thread reads the sensors in a synchronized method of the controller, sleeping
 * inside it; the controller's run() returns while that thread holds the controller's monitor.
 */
public class LockedAtReturn extends Thread {
    private final CurrentRobotState state;
    private final MessagePasser mp;
    private final int[] latest = new int[8];

    public LockedAtReturn(CurrentRobotState state, MessagePasser mp) {
        this.state = state;
        this.mp = mp;
        new Thread(() -> {
            while (true) {
                refresh();
                try {
                    Thread.sleep(5);
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "sensor-manager").start();
    }

    private synchronized void refresh() {
        for (int i = 0; i < 8; i++) {
            latest[i] = state.getSensorValues()[i].getDistValue();
        }
        try {
            Thread.sleep(40);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private synchronized int front() {
        return StrictMath.max(latest[2], latest[3]);
    }

    @Override
    public void run() {
        for (int i = 0; i < 15; i++) {
            state.getMotorState().setMotorSpeeds(front() > 500 ? 3 : 5, 5);
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                return;
            }
        }
        mp.sendMessage("returns");
    }
}
