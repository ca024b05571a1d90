package org.kheperasim.sim.engine.body;

import org.kheperasim.sim.engine.robot.RobotType;

/**
 * The Khepera's position mode for one wheel ({@code C,l,r} with the profile set by
 * {@code J,max_l,acc_l,max_r,acc_r}): every motor period (10 ms) the wheel's speed moves toward the
 * target along a trapezoid, accelerating by the profile's acceleration up to its maximum speed and
 * braking so that it arrives with speed zero.
 *
 * <p>Units, as on the robot: positions in encoder pulses; speed in pulses per 10 ms (the speed
 * unit); acceleration in 1/256 of a speed unit per 10 ms, so the default 64 adds a quarter unit
 * each period. The reference gives the defaults (20, 64) but not the acceleration's unit; this one
 * is the motion controller's usual scaling and is marked uncertain in docs/protocol-server.md.
 *
 * <p>The wheel is closed-loop on its own encoder, like the robot's: a wheel that is blocked keeps
 * its error and never reports "on target".
 */
public final class PositionControl {
    /** The acceleration unit: 1/256 of a speed unit per 10 ms. */
    public static final double ACCELERATION_SCALE = 1.0 / 256;
    /** Closer than this to the target, pulses, counts as on target. */
    public static final double ON_TARGET_PULSES = 0.5;

    /** The robot's speed limit, speed units. */
    private final int speedLimit;
    private int maxSpeed;
    private int acceleration;
    private int target;
    private double speed;
    private boolean active;

    /**
     * @param drive the robot's drive: its speed limit and the reset defaults of a move's profile
     */
    public PositionControl(RobotType.Drive drive) {
        this.speedLimit = drive.maxSpeed();
        this.maxSpeed = drive.moveSpeed();
        this.acceleration = drive.acceleration();
    }

    /**
     * @param maxSpeed maximum speed of a move, speed units (pulses per 10 ms), taken as its magnitude
     * @param acceleration acceleration, 1/256 speed unit per 10 ms, taken as its magnitude
     */
    public void profile(int maxSpeed, int acceleration) {
        this.maxSpeed = StrictMath.min(speedLimit, StrictMath.abs(maxSpeed));
        this.acceleration = StrictMath.abs(acceleration);
    }

    /** @return the maximum speed of a move, speed units */
    public int maxSpeed() {
        return maxSpeed;
    }

    /** @return the acceleration, 1/256 speed unit per 10 ms */
    public int acceleration() {
        return acceleration;
    }

    /**
     * Start a move to an absolute counter value; the current speed carries over.
     *
     * @param target the position counter to reach, pulses
     * @param currentSpeed the wheel's speed now, speed units
     */
    public void moveTo(int target, int currentSpeed) {
        this.target = target;
        this.speed = currentSpeed;
        this.active = true;
    }

    /** Leave position mode (a speed or PWM command arrived, or the robot was stopped). */
    public void cancel() {
        active = false;
        speed = 0;
    }

    /** @return true while in position mode (the move may be finished: see {@link #onTarget}) */
    public boolean active() {
        return active;
    }

    /** @return the target counter value, pulses */
    public int target() {
        return target;
    }

    /**
     * @param position the wheel's counter now, pulses (fractional: the simulator's travel)
     * @return true when the wheel is within half a pulse of its target and at rest
     */
    public boolean onTarget(double position) {
        return StrictMath.abs(target - position) < ON_TARGET_PULSES && speed == 0;
    }

    /**
     * One motor period: the speed for the next 10 ms.
     *
     * @param position the wheel's counter now, pulses
     * @return the wheel speed to set, speed units (whole: the robot's speed register is an integer)
     */
    public int update(double position) {
        double error = target - position;
        double remaining = StrictMath.abs(error);
        double accel = StrictMath.max(acceleration * ACCELERATION_SCALE, 1e-9);
        if (remaining < ON_TARGET_PULSES) {
            speed = 0;
            return 0;
        }
        // The fastest speed from which the wheel can still brake within the remaining distance,
        // never more than the remaining distance in one period (a speed unit is a pulse per period).
        double brake = StrictMath.sqrt(2 * accel * remaining);
        double magnitude = StrictMath.min(StrictMath.min(maxSpeed, brake), StrictMath.abs(speed) + accel);
        magnitude = StrictMath.min(magnitude, remaining);
        if (magnitude < 1) {
            // The speed register holds whole units: creep the last pulses at one unit.
            magnitude = StrictMath.min(1, remaining);
        }
        speed = StrictMath.signum(error) * magnitude;
        return (int) StrictMath.signum(error) * (int) StrictMath.max(1, StrictMath.rint(magnitude));
    }
}
