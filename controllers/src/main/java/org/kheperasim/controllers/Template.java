package org.kheperasim.controllers;

import org.kheperasim.api.*;

/**
 * A template for your own controller, in the classic shape of the WSU simulator (the paper's
 * Appendix). Copy this file, rename the class (and the constructor) to your controller's name,
 * and fill in the places marked TODO.
 *
 * <p>It runs unchanged in the simulator and on the real robot. In the simulator,
 * {@code Thread.sleep(ms)} sleeps simulated time, and every API call costs a little simulated
 * time; so a loop that reads sensors always moves time forward.
 *
 * <p>Prefer a shorter start? Extend {@link Controller} instead and write only {@code doWork()}.
 */
public class Template extends Thread {
    // Do NOT modify these fields: they are your robot.
    private CurrentRobotState currentData;
    private MessagePasser messagePasser;
    private Sensor[] sensors;   // sensors[0..7]: 0 left, 1 front-left 45°, 2-3 front, 4 right 45°, 5 right, 6-7 back
    private Motor motorState;   // setMotorSpeeds(left, right): -127..127, 1 unit is about 8 mm/s
    private Gripper gripper;    // arm up/down, fingers open/close
    private volatile boolean active;

    // TODO: add your own fields here, e.g. thresholds.
    private int wallThreshold = 600;   // proximity 0..1023, higher = nearer; ~600 is about 20 mm

    /** The simulator (or the robot link) creates the controller with the robot's state. */
    public Template(CurrentRobotState data, MessagePasser mp) {
        currentData = data;
        messagePasser = mp;
        active = true;
    }

    /** Called when the controller must stop: end your loops soon after. */
    public void killControl() {
        active = false;
    }

    /** Your controller's program. */
    public void run() {
        sensors = currentData.getSensorValues();   // live: the values stay fresh
        motorState = currentData.getMotorState();
        gripper = currentData.getGripper();
        messagePasser.sendMessage("Template started");

        while (active) {
            // TODO: replace this with your behaviour. This one drives forward and turns right
            // on the spot while something is close in front.
            if (sensors[2].getDistValue() > wallThreshold || sensors[3].getDistValue() > wallThreshold) {
                motorState.setMotorSpeeds(3, -3);
            } else {
                motorState.setMotorSpeeds(5, 5);
            }
            sleepTime(50);   // decide 20 times a second
        }
        motorState.setMotorSpeeds(0, 0);
    }

    private void sleepTime(int millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            active = false;
        }
    }
}
