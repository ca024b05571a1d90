package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.Sensor;

/** Reads a sensor 50,000 times in a busy loop, then reports the simulated time that took. */
public class BusyReader extends Thread {
    private final CurrentRobotState state;
    private final MessagePasser mp;

    public BusyReader(CurrentRobotState state, MessagePasser mp) {
        this.state = state;
        this.mp = mp;
    }

    @Override
    public void run() {
        Sensor[] s = state.getSensorValues();
        long start = System.nanoTime();
        long sum = 0;
        for (int i = 0; i < 50_000; i++) {
            sum += s[2].getDistValue();
        }
        mp.sendMessage("elapsed " + (System.nanoTime() - start) + " sum " + (sum > 0));
    }
}
