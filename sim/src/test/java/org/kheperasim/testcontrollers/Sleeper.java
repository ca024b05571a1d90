package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/** Sleeps 100 ms ten times and reports what the clocks said each time. */
public class Sleeper extends Thread {
    private final MessagePasser mp;

    public Sleeper(CurrentRobotState state, MessagePasser mp) {
        this.mp = mp;
    }

    @Override
    public void run() {
        long startMillis = System.currentTimeMillis();
        long startNanos = System.nanoTime();
        for (int i = 0; i < 10; i++) {
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                return;
            }
        }
        mp.sendMessage("millis " + (System.currentTimeMillis() - startMillis) + " nanos " + (System.nanoTime() - startNanos));
    }
}
