package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/** Sleeps forever and swallows every interruption, ignoring the stop: it has no killControl(). */
public class Forever extends Thread {
    public Forever(CurrentRobotState state, MessagePasser mp) {
    }

    @Override
    public void run() {
        while (true) {
            try {
                Thread.sleep(50);
            } catch (InterruptedException e) {
                // keep going
            }
        }
    }
}
