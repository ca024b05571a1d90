package org.kheperasim.testcontrollers;

/** Not a usable controller: no (CurrentRobotState, MessagePasser) constructor. */
public class NoConstructor extends Thread {
    public NoConstructor(String name) {
        super(name);
    }
}
