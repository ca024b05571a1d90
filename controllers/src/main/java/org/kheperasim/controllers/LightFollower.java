package org.kheperasim.controllers;

import org.kheperasim.api.Controller;
import org.kheperasim.api.IrSensor;
import org.kheperasim.api.SensorFilter;

/**
 * Goes to the light (the paper's third assignment: follow light beacons to a goal). The ambient
 * light sensors read about 480 in darkness and less the brighter it is; this controller:
 *
 * <ul>
 *   <li>in the open (no wall within sensing range), turns towards the brightest of its six forward
 *       sensors and drives at it, a Braitenberg "lover";
 *   <li>between walls (a maze, a doorway), keeps its left side to the wall as {@link MazeExplorer}
 *       does, and counts the beacons it passes (a light that grows brighter, then fades);
 *   <li>stops for good under a lamp bright enough to be the goal (a reading under {@link #GOAL}).
 * </ul>
 *
 * Both sensor kinds go through a {@link SensorFilter}, so a flicker or a spike neither turns the robot
 * nor ends its run.
 */
public class LightFollower extends Controller {
    /** A light reading under this: the robot is under the goal's lamp. */
    static final int GOAL = 110;
    /** Brightness (480 less the reading) from which a light counts as seen. */
    private static final int SEE = 40;
    /** About the reading in darkness. */
    private static final int DARK = 480;
    private static final int CRUISE = 7;
    private static final int SETPOINT = 420;
    private static final double GAIN = 0.006;
    private static final int FRONT_BLOCKED = 350;
    private static final int WALL_LOST = 80;
    private static final int NEAR = 100;
    /** The bearing each of sensors 0..5 looks at, degrees to the left. */
    private static final int[] BEARING = {90, 45, 10, -10, -45, -90};

    private final SensorFilter prox = new SensorFilter();
    private final SensorFilter light = new SensorFilter(8, 3, 150);
    private boolean arrived;
    private int lost;
    private int brightest = DARK;
    private int beacons;
    /** Steps (50 ms) for which the light is not followed: the robot has just reached a beacon. */
    private int leaving;
    /** Dead reckoning from the encoders: where the robot is, to remember where the beacons it passed were. */
    private Odometry odometry;
    private double brightestX;
    private double brightestY;
    private final java.util.List<double[]> passed = new java.util.ArrayList<>();

    @Override
    protected void setup() {
        odometry = new Odometry(0, 0, 0, leftPosition(), rightPosition());
    }

    @Override
    protected void doWork() {
        if (arrived) {
            stopMotors();
            sleepMillis(500);
            return;
        }
        prox.addProximity(sensors());
        light.addLight(sensors());
        int dimmest = DARK;
        int best = 0;
        for (int i = 0; i < 8; i++) {
            dimmest = StrictMath.min(dimmest, light.value(i));
            if (i < 6 && light.value(i) < light.value(best)) {
                best = i;
            }
        }
        if (dimmest < GOAL) {
            arrived = true;
            stopMotors();
            print("under the goal's lamp (light " + dimmest + ") after " + beacons + " beacons; stopping here");
            return;
        }
        odometry.update(leftPosition(), rightPosition());
        countBeacons(dimmest);
        int left = prox.value(IrSensor.LEFT_90);
        int left45 = prox.value(IrSensor.LEFT_45);
        int front = StrictMath.max(prox.value(IrSensor.FRONT_LEFT), prox.value(IrSensor.FRONT_RIGHT));
        int right = StrictMath.max(prox.value(IrSensor.RIGHT_45), prox.value(IrSensor.RIGHT_90));
        boolean open = StrictMath.max(StrictMath.max(left, left45), StrictMath.max(front, right)) < NEAR;
        if (front > FRONT_BLOCKED || left45 > 800) {
            // Wall ahead: turn on the spot towards the freer side (right, when following a left wall;
            // either way in a beacon's corner, where the way on is the open side).
            boolean atBeacon = DARK - dimmest > 3 * SEE;
            if (atBeacon) {
                leaving = 40;   // at a beacon: turn to the open side and leave it, not back to it
            }
            if (!atBeacon || StrictMath.max(left, left45) > right) {
                setSpeeds(4, -4);
            } else {
                setSpeeds(-4, 4);
            }
        } else if (open && leaving == 0 && DARK - light.value(best) > SEE && !passedLies(BEARING[best])) {
            int turn = (int) StrictMath.round(BEARING[best] / 30.0); // towards the light, harder the further off
            setSpeeds(CRUISE - turn, CRUISE + turn);
            lost = 0;
        } else if (left < WALL_LOST && left45 < WALL_LOST) {
            lost++;
            setSpeeds(lost < 120 ? 2 : CRUISE, lost < 120 ? 7 : CRUISE);   // around a wall end, or on to find a wall
        } else {
            lost = 0;
            double error = StrictMath.max(left, left45 - 150) - SETPOINT;
            int turn = (int) StrictMath.round(StrictMath.max(-3, StrictMath.min(3, GAIN * error)));
            setSpeeds(CRUISE + turn, CRUISE - turn);
        }
        leaving = StrictMath.max(0, leaving - 1);
        sleepMillis(50);
    }

    /** A beacon passed: the light grew bright, then faded again. */
    private void countBeacons(int dimmest) {
        if (dimmest < brightest) {
            brightest = dimmest;
            brightestX = odometry.x();
            brightestY = odometry.y();
        } else if (brightest < DARK - 3 * SEE && dimmest > brightest + 2 * SEE) {
            beacons++;
            passed.add(new double[] {brightestX, brightestY});
            print("passed beacon " + beacons + " (light " + brightest + ")");
            brightest = dimmest;
        }
    }

    /**
     * @param bearingDeg a light's direction, degrees left of ahead @return true if a beacon already passed lies that
     *     way, near
     */
    private boolean passedLies(double bearingDeg) {
        double toward = odometry.heading() + StrictMath.toRadians(bearingDeg);
        for (double[] b : passed) {
            double dx = b[0] - odometry.x();
            double dy = b[1] - odometry.y();
            if (StrictMath.hypot(dx, dy) < 350) {
                double off = StrictMath.abs(
                        StrictMath.IEEEremainder(StrictMath.atan2(dy, dx) - toward, 2 * StrictMath.PI));
                if (off < StrictMath.toRadians(60)) {
                    return true;
                }
            }
        }
        return false;
    }
}
