package org.kheperasim.controllers;

import java.util.Random;
import org.kheperasim.api.Controller;

/**
 * Gathers bottle caps under a lamp, for the {@code two-rooms} arena: it wanders with the arm down
 * and the fingers open; when something breaks the optical barrier between the fingers it closes
 * them, and the resistivity sensor tells a cap (conductive) from a wall (nothing held). With a cap
 * it raises the arm and follows the light through the doorway; near the lamp it lowers the arm,
 * lets go, turns round and goes back for the next.
 *
 * <p>Only the robot's own sensors are used (proximity, ambient light, the gripper's barrier and
 * resistivity, the wheel encoders to notice being stuck), so it runs unchanged on a real Khepera
 * with a gripper turret.
 */
public class CapGatherer extends Controller {
    private static final int STEP_MS = 20;
    private static final int CRUISE = 8;
    /** Light readings fall from about 480 in the dark toward 20 next to a lamp. */
    private static final int LAMP_SEEN = 430;
    private static final int AT_LAMP = 140;
    private static final int NEAR_PILE = 230;
    /** Closer to the lamp than this reading, a cap has been delivered already: leave it there. */
    private static final int NEAR_LAMP = 200;
    private static final int OBSTACLE = 350;

    private enum Phase { SEARCH, DELIVER }

    private Phase phase = Phase.SEARCH;
    private final Random random = new Random(7);
    private int wanderTurn;
    private int wanderSteps;
    private int delivered;
    private int lastLeft;
    private int lastRight;
    private int stuckSteps;
    /** While carrying: the brightest reading so far, and how many steps since it last got brighter. */
    private int bestLight = 1023;
    private int stepsWithoutProgress;
    /** Steps left of straight exploring after giving up on a light that led nowhere. */
    private int exploreSteps;
    /** Carrying, this long without getting nearer the lamp is a livelock (a corner beside the doorway). */
    private static final int GIVE_UP_MS = 8000;

    @Override
    protected void setup() {
        release();
        lowerArm();
        print("searching for caps");
    }

    @Override
    protected void doWork() {
        if (stuck()) {
            escape();
            return;
        }

        if (phase == Phase.SEARCH) {
            search();
        } else {
            deliver();
        }
        sleepMillis(STEP_MS);
    }

    private void search() {
        boolean nearLamp = brightest() < NEAR_LAMP;
        if (objectBetweenFingers()) {
            stopMotors();
            if (!nearLamp && grab() && gripper().getResistivity() > 0) {
                raiseArm();
                phase = Phase.DELIVER;
                bestLight = 1023;
                stepsWithoutProgress = 0;
                print("got a cap (resistivity " + gripper().getResistivity() + ")");
                return;
            }
            // A wall, or a cap already delivered: let go, back off and turn away.
            release();
            drive(-6, -6, 500);
            turnRandomly();
            return;
        }
        if (avoid(false)) {
            return;
        }
        if (nearLamp) {
            steerAwayFromLight();
        } else if (exploreSteps > 0) {
            exploreSteps--;
            wander();
        } else if (brightest() < LAMP_SEEN) {
            // The lamp is in sight: this is the target room, where the caps have been brought.
            // Head for the dark, which is back through the doorway to the caps still to fetch.
            steerFromLight();
        } else {
            // Something small just ahead on one side: steer toward it so it comes between the fingers.
            int p2 = prox(2);
            int p3 = prox(3);
            if (p2 > 120 && p2 > p3 + 60) {
                setSpeeds(CRUISE - 3, CRUISE);
            } else if (p3 > 120 && p3 > p2 + 60) {
                setSpeeds(CRUISE, CRUISE - 3);
            } else {
                wander();
            }
        }
    }

    private void deliver() {
        int bright = brightest();
        int nearest = 0;
        for (int i = 0; i < 6; i++) {
            nearest = Math.max(nearest, prox(i));
        }
        // At the lamp, or close to it with the way blocked (by caps already delivered): put it down.
        if (bright < AT_LAMP || (bright < NEAR_PILE && nearest > OBSTACLE)) {
            stopMotors();
            lowerArm();
            release();
            delivered++;
            print("delivered cap " + delivered);
            drive(-6, -6, 800);
            // Turn about half a turn and head back toward the doorway.
            drive(6, -6, 1700);
            phase = Phase.SEARCH;
            // It came from the doorway: head straight back that way for a while.
            wanderTurn = 0;
            wanderSteps = 300;
            return;
        }
        if (bright < bestLight - 10) {
            bestLight = bright;
            stepsWithoutProgress = 0;
        } else if (++stepsWithoutProgress * STEP_MS > GIVE_UP_MS) {
            // Turning between a wall and the light seen through the doorway gets nowhere: back off,
            // turn a random way and go exploring for a while before following the light again.
            stepsWithoutProgress = 0;
            bestLight = bright;
            drive(-6, -6, 700);
            turnRandomly();
            exploreSteps = 100 + random.nextInt(100);
            return;
        }
        if (avoid(true)) {
            return;
        }
        if (exploreSteps > 0) {
            exploreSteps--;
            wander();
        } else if (bright < LAMP_SEEN) {
            steerTowardLight();
        } else {
            wander();
        }
    }

    /**
     * Keep off walls: turn on the spot away from whatever is near a side. With the arm down the
     * front sensors are left to the gripper (a cap ahead must come between the fingers).
     *
     * @param useFront also treat something just ahead as an obstacle
     * @return true when it has steered
     */
    private boolean avoid(boolean useFront) {
        int left = Math.max(prox(0), prox(1));
        int right = Math.max(prox(4), prox(5));
        if (useFront) {
            left = Math.max(left, prox(2));
            right = Math.max(right, prox(3));
        }
        if (left > 800 && right > 800) {
            drive(-6, -6, 400);
            turnRandomly();
            return true;
        }
        // Commit to each turn for a while: turning only until the reading drops invites dithering
        // between two walls.
        if (left > OBSTACLE && left >= right) {
            drive(6, -6, 200 + random.nextInt(400));
            return true;
        }
        if (right > OBSTACLE) {
            drive(-6, 6, 200 + random.nextInt(400));
            return true;
        }
        return false;
    }

    /** Steer so the brighter side (lower reading) comes ahead. */
    private void steerTowardLight() {
        int l = lux(0) + lux(1) + lux(2);
        int r = lux(3) + lux(4) + lux(5);
        int back = Math.min(lux(6), lux(7));
        if (back < Math.min(lux(2), lux(3)) - 20) {
            setSpeeds(6, -6);
        } else if (l < r - 15) {
            setSpeeds(CRUISE - 4, CRUISE);
        } else if (r < l - 15) {
            setSpeeds(CRUISE, CRUISE - 4);
        } else {
            setSpeeds(CRUISE, CRUISE);
        }
    }

    /** Steer so the darker side (higher reading) comes ahead. */
    private void steerFromLight() {
        int l = lux(0) + lux(1) + lux(2);
        int r = lux(3) + lux(4) + lux(5);
        if (Math.min(lux(2), lux(3)) < Math.min(lux(6), lux(7)) - 20) {
            setSpeeds(6, -6);
        } else if (l < r - 15) {
            setSpeeds(CRUISE, CRUISE - 4);
        } else if (r < l - 15) {
            setSpeeds(CRUISE - 4, CRUISE);
        } else {
            wander();
        }
    }

    /** Turn the back to the lamp (a committed half turn), then go straight on. */
    private void steerAwayFromLight() {
        if (Math.min(lux(2), lux(3)) < Math.min(lux(6), lux(7))) {
            drive(6, -6, 1700);
        }
        setSpeeds(CRUISE, CRUISE);
    }

    private void wander() {
        if (wanderSteps <= 0) {
            wanderSteps = 50 + random.nextInt(100);
            wanderTurn = random.nextInt(5) - 2;
        }
        wanderSteps--;
        setSpeeds(CRUISE - wanderTurn, CRUISE + wanderTurn);
    }

    private void turnRandomly() {
        int ms = 300 + random.nextInt(900);
        if (random.nextBoolean()) {
            drive(6, -6, ms);
        } else {
            drive(-6, 6, ms);
        }
    }

    private int brightest() {
        int min = Integer.MAX_VALUE;
        for (int i = 0; i < 8; i++) {
            min = Math.min(min, lux(i));
        }
        return min;
    }

    /** @return true when the wheels have been asked to move but the encoders have hardly changed for 2 s */
    private boolean stuck() {
        int l = leftPosition();
        int r = rightPosition();
        boolean moving = motor().getLeftSpeed() != 0 || motor().getRightSpeed() != 0;
        if (moving && Math.abs(l - lastLeft) + Math.abs(r - lastRight) < 4) {
            stuckSteps++;
        } else {
            stuckSteps = 0;
            lastLeft = l;
            lastRight = r;
        }
        return stuckSteps * STEP_MS > 2000;
    }

    private void escape() {
        stuckSteps = 0;
        drive(-6, -6, 700);
        turnRandomly();
        lastLeft = leftPosition();
        lastRight = rightPosition();
    }

    private int prox(int i) {
        return sensors()[i].getDistValue();
    }

    private int lux(int i) {
        return sensors()[i].getLightValue();
    }

    private void drive(int left, int right, int ms) {
        setSpeeds(left, right);
        sleepMillis(ms);
        stopMotors();
    }
}
