/*
 * WallFollower.java: the Appendix controller of the WSU Khepera simulator paper (ASEE 2003),
 * "Robot.java, created on July 27, 2001 by bill", as the paper printed it. Only three things
 * differ: the package and import lines, the class name (Robot -> WallFollower), and the paper's OCR
 * errors (closelndex -> closeIndex, sensors][i] -> sensors[i], inti=0;i<5;i++ -> int i = 0; i < 5;
 * i++, iftempVal -> if (tempVal, "/I" -> "//", and "closeIndex2 = 3" -> "closeIndex2 != 3").
 *
 * It follows the wall on its left through a maze whose walls are continuous (no islands).
 */
package org.kheperasim.controllers;

import org.kheperasim.api.*;

/**
 * @author bill
 * @version
 * Wall Follower
 */
public class WallFollower extends Thread {
    // Do NOT Modify these fields
    private CurrentRobotState currentData;
    private MessagePasser messagePasser;
    private Sensor[] sensors;
    private Motor motorState;
    private int gripperState;
    private int armState;
    private int resistivity;
    private boolean objPresent;
    private boolean active;

    // Add your own fields here....
    private int distThreshold = 600;

    /** Creates new Robot */
    public WallFollower(CurrentRobotState data, MessagePasser mp) {
        currentData = data;
        messagePasser = mp;
        active = true;
    }

    private void getRobotObjects() {
        sensors = currentData.getSensorValues();
        motorState = currentData.getMotorState();
    }

    private void setForwardSpeed() {
        motorState.setMotorSpeeds(3, 3);
    }

    private void setSpeed(int left, int right) {
        motorState.setMotorSpeeds(left, right);
    }

    private void testProximity() {
        int max = 0;
        int closeIndex = -1;
        int closeIndex2 = -1;

        for (int i = 0; i < 5; i++) {
            int tempVal = sensors[i].getDistValue();
            if (tempVal > distThreshold) {
                if (tempVal > max) {
                    max = tempVal;
                    closeIndex2 = closeIndex;
                    closeIndex = i;
                }
            }
        }
        if (closeIndex == 0) {
            if (closeIndex2 != 2 && closeIndex2 != 3)
                motorState.setMotorSpeeds(3, -1);
            else
                motorState.setMotorSpeeds(3, -5);
            return;
        }
        if (closeIndex == 1) {
            if (closeIndex2 != 2 && closeIndex2 != 3)
                motorState.setMotorSpeeds(3, 1);
            else
                motorState.setMotorSpeeds(3, -5);
            return;
        }
        if (closeIndex == 2 || closeIndex == 3) {
            motorState.setMotorSpeeds(3, -5);
            return;
        }
        if (closeIndex == 4 || closeIndex == 5) {
            if (closeIndex2 == 2 || closeIndex2 == 3)
                motorState.setMotorSpeeds(3, -5);
            else
                motorState.setMotorSpeeds(-1, 3);
            return;
        }
        motorState.setMotorSpeeds(1, 3);
    }

    private void findwall() {
        setSpeed(3, 3);
        while (sensors[2].getDistValue() < distThreshold)
            sleepTime(100);

        setSpeed(2, -2);
        while (sensors[0].getDistValue() < distThreshold)
            sleepTime(100);
        setSpeed(0, 0);
    }

    private void sleepTime(int time) {
        try {
            Thread.sleep((long) time);
        } catch (InterruptedException e) {}
    }

    public void killControl() {
        active = false;
    }

    public void run() {
        getRobotObjects();
        findwall();
        while (active) {
            testProximity();
        }
    }
}
