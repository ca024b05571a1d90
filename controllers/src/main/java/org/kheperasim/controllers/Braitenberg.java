package org.kheperasim.controllers;

import org.kheperasim.api.Controller;
import org.kheperasim.api.IrSensor;
import org.kheperasim.api.Motor;

/**
 * An obstacle avoider in the manner of Braitenberg's vehicles: each wheel is driven by a weighted
 * sum of the proximity sensors, so an obstacle on the left speeds up the left wheel and slows the
 * right one, turning the robot away. Something straight ahead makes it turn on the spot, towards
 * the freer side. One decision every 100 ms.
 *
 * <p>Written once for every robot: its speeds are in mm/s and its readings a fraction of the top of
 * its robot's scale, each turned into the robot's own numbers ({@link Motor#getMmPerSecondPerUnit()},
 * {@link Motor#getMaxSpeed()}, {@link org.kheperasim.api.Sensor#getMaxDistValue()}). On a Khepera
 * (8 mm/s a unit, readings 0..1023) every speed it sets is the one it set in Khepera units: 6 units
 * cruising, 4 spinning, at most 15. It reads sensors 0..5 in the Khepera's order, which the bundled
 * robots keep (docs/robot-files.md).
 */
public class Braitenberg extends Controller {
    /** Cruising speed, mm/s (6 units on a Khepera). */
    private static final double CRUISE_MM_S = 48;
    /** Each wheel's speed when it turns on the spot, mm/s (4 units on a Khepera). */
    private static final double SPIN_MM_S = 32;
    /** The fastest either wheel goes, mm/s (15 units on a Khepera). */
    private static final double LIMIT_MM_S = 120;
    /**
     * The scale the weights and the threshold are written on: a reading as a fraction of its robot's
     * top, times 1023 (on a Khepera the reading itself).
     */
    private static final double SCALE = 1023;
    /**
     * How strongly each of sensors 0..5 (left 90° to right 90°) pushes the robot to turn right: per 100
     * of {@link #SCALE}, in turns of {@link #TURN_MM_S} each.
     */
    private static final double[] TURN_WEIGHTS = {0.4, 0.8, 1.2, -1.2, -0.8, -0.4};
    /** One turn of the weights, mm/s taken off one wheel and given to the other (1 unit on a Khepera). */
    private static final double TURN_MM_S = 8;
    /** Proximity at which the front counts as blocked, on {@link #SCALE} (49 % of the robot's top). */
    private static final double BLOCKED = 500;

    /** This robot's numbers, read in {@link #setup()}: one unit of speed, mm/s; its limit; its top reading. */
    private double mmPerSecondPerUnit;
    private int limit;
    private int maxReading;

    @Override
    protected void setup() {
        Motor motor = motor();
        mmPerSecondPerUnit = motor.getMmPerSecondPerUnit();
        limit = (int) StrictMath.min(motor.getMaxSpeed(), StrictMath.floor(LIMIT_MM_S / mmPerSecondPerUnit));
        maxReading = sensors()[0].getMaxDistValue();
    }

    @Override
    protected void doWork() {
        double frontLeft = level(proximity(IrSensor.FRONT_LEFT));
        double frontRight = level(proximity(IrSensor.FRONT_RIGHT));
        double turn = 0;
        for (int i = 0; i < TURN_WEIGHTS.length; i++) {
            turn += TURN_WEIGHTS[i] * level(sensors()[i].getDistValue()) / 100.0 * TURN_MM_S;
        }
        if (StrictMath.max(frontLeft, frontRight) > BLOCKED) {
            // Spin away from the nearer side; with nothing to tell them apart, turn right.
            int spin = units(SPIN_MM_S);
            if (turn >= 0) {
                setSpeeds(spin, -spin);
            } else {
                setSpeeds(-spin, spin);
            }
        } else {
            setSpeeds(units(CRUISE_MM_S + turn), units(CRUISE_MM_S - turn));
        }
        sleepMillis(100);
    }

    /** @return a reading on {@link #SCALE}: exactly the reading on a Khepera, whose top is 1023 */
    private double level(int reading) {
        return reading * SCALE / maxReading;
    }

    /** @return a speed in mm/s as the nearest whole number of the robot's units, within the limit */
    private int units(double mmPerSecond) {
        int speed = (int) StrictMath.round(mmPerSecond / mmPerSecondPerUnit);
        return StrictMath.max(-limit, StrictMath.min(limit, speed));
    }
}
