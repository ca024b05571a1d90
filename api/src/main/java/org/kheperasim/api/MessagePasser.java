package org.kheperasim.api;

import org.kheperasim.api.spi.RobotPort;

/**
 * Sends text from a controller to the person watching it: the simulator's console, or the lab
 * host's terminal. Each message is stamped with the robot's time.
 */
public final class MessagePasser {
    private final RobotPort port;

    /** @param port the backend that delivers messages (backends construct this, students do not) */
    public MessagePasser(RobotPort port) {
        this.port = port;
    }

    /** @param message one line of text to show */
    public void sendMessage(String message) {
        port.message(String.valueOf(message));
    }
}
