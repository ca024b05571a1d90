package org.kheperasim.testcontrollers;

import java.util.ArrayList;
import java.util.List;
import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/**
 * The WSU pattern: the constructor starts a sensor-manager thread that reads the sensors into a
 * shared object every 53 ms (holding its lock while it reads, and even while it sleeps 8 ms in it);
 * the controller's thread steers from that object every 20 ms. It reports the order in which
 * the two threads ran during the first 200 ms, with their simulated times in ms.
 */
public class SensorManager extends Thread {
    private final CurrentRobotState state;
    private final MessagePasser mp;
    private final List<String> events = new ArrayList<>();
    private final int[] latest = new int[8];
    private volatile boolean done;
    private boolean reported;

    public SensorManager(CurrentRobotState state, MessagePasser mp) {
        this.state = state;
        this.mp = mp;
        Thread reader = new Thread(this::readForever, "sensor-manager");
        reader.start();
    }

    private void readForever() {
        while (!done) {
            refresh();
            try {
                Thread.sleep(45);
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    private synchronized void refresh() {
        if (!reported) {
            events.add("R" + System.currentTimeMillis() % 100_000);
        }
        for (int i = 0; i < 8; i++) {
            latest[i] = state.getSensorValues()[i].getDistValue();
        }
        try {
            Thread.sleep(8);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private synchronized int front() {
        if (!reported) {
            events.add("M" + System.currentTimeMillis() % 100_000);
        }
        return Math.max(latest[2], latest[3]);
    }

    @Override
    public void run() {
        long start = System.currentTimeMillis();
        while (!done) {
            int front = front();
            if (front > 500) {
                state.getMotorState().setMotorSpeeds(3, -3);
            } else {
                state.getMotorState().setMotorSpeeds(5, 5);
            }
            if (!reported && System.currentTimeMillis() - start >= 200) {
                reported = true;
                synchronized (this) {
                    mp.sendMessage("order " + String.join(" ", events));
                }
            }
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                return;
            }
        }
    }
}
