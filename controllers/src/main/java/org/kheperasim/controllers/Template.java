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
    private int wallThreshold = 500;   // proximity 0..1023, higher = nearer; ~500 is about 25 mm
    private int sideThreshold = 700;   // a side sensor this high: something right beside the robot

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

        int lastTravel = 0;   // wheel pulses at the last check
        int stalled = 0;      // checks in a row that the wheels turned but the robot did not move
        while (active) {
            // TODO: replace this with your behaviour. This one drives forward, turns on the spot
            // away from whatever is close ahead, veers away from what is close beside it, and backs
            // out when it finds itself stuck.
            int left = Math.max(sensors[1].getDistValue(), sensors[2].getDistValue());    // front-left and 45° left
            int right = Math.max(sensors[3].getDistValue(), sensors[4].getDistValue());   // front-right and 45° right
            int travel = motorState.getLeftPosition() + motorState.getRightPosition();
            boolean forward = false;
            if (stalled >= 10) {
                // Half a second of driving forward without moving: something the sensors miss (a
                // thin wall end, a lamp) holds the robot. Back off and turn; every robot needs this.
                motorState.setMotorSpeeds(-3, -3);
                sleepTime(500);
                motorState.setMotorSpeeds(3, -3);
                sleepTime(400);
                stalled = 0;
                travel = motorState.getLeftPosition() + motorState.getRightPosition();
            } else if (left > wallThreshold || right > wallThreshold) {
                // Something close ahead: turn on the spot, away from the nearer side.
                if (left >= right) {
                    motorState.setMotorSpeeds(3, -3);
                } else {
                    motorState.setMotorSpeeds(-3, 3);
                }
            } else if (sensors[0].getDistValue() > sideThreshold) {
                motorState.setMotorSpeeds(5, 2);   // close on the left: veer right
                forward = true;
            } else if (sensors[5].getDistValue() > sideThreshold) {
                motorState.setMotorSpeeds(2, 5);   // close on the right: veer left
                forward = true;
            } else {
                motorState.setMotorSpeeds(5, 5);   // nothing near: straight ahead at 40 mm/s
                forward = true;
            }
            // Driving forward, the wheels move about 50 pulses per 50 ms; under 10, they are held.
            stalled = forward && travel - lastTravel < 10 ? stalled + 1 : 0;
            lastTravel = travel;
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
