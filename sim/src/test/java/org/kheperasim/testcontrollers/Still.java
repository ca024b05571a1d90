package org.kheperasim.testcontrollers;

import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;

/** Stands still and keeps its link polling: its readings show what comes in front of it. */
public class Still extends Thread {
    public Still(CurrentRobotState state, MessagePasser mp) {
    }

    @Override
    public void run() {
        while (true) {
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                return;
            }
        }
    }
}
