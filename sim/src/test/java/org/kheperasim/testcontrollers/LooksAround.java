package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/**
 * Looks around in its constructor, as student code does in field initialisers: the time (to seed
 * a random generator), its thread, a lock. The constructor sees the run's start time.
 */
public class LooksAround extends Thread {
    private final long seed = System.currentTimeMillis();
    private final String constructedOn = Thread.currentThread().getName();
    private final MessagePasser mp;

    public LooksAround(CurrentRobotState state, MessagePasser mp) {
        this.mp = mp;
        synchronized (this) {
            state.getSensorValues();
        }
    }

    @Override
    public void run() {
        mp.sendMessage("seed " + seed + " constructed on a thread " + !constructedOn.isEmpty() + " runs as itself "
                + (Thread.currentThread() == this));
    }
}
