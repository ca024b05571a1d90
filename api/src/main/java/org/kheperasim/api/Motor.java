package org.kheperasim.api;

import org.kheperasim.api.spi.RobotPort;

/**
 * The two wheel motors and their position counters (encoders). A live view.
 *
 * <p>Speeds are in the robot's speed units ({@link #getMmPerSecondPerUnit()}, up to
 * {@link #getMaxSpeed()}); on the Khepera one unit is one encoder pulse per 10 ms, about 8 mm/s,
 * and the robot accepts −127..127 (an e-puck: steps/s, −1000..1000). Positions are in pulses, about 0.08 mm of wheel
 * travel each; they stop counting while the robot is blocked, which is how a controller can tell it is stuck.
 */
public final class Motor {
    /** The largest speed magnitude the Khepera accepts, speed units (another robot's: {@link #getMaxSpeed()}). */
    public static final int MAX_SPEED = 127;

    private final RobotPort port;

    Motor(RobotPort port) {
        this.port = port;
    }

    /**
     * Set both wheel speeds. The command reaches the robot after the serial line's transmission
     * time, as on the real robot.
     *
     * @param left left wheel speed, −127..127 speed units on a Khepera (≈ 8 mm/s each), the robot's
     *     own units and limit on another; positive drives forward
     * @param right right wheel speed, likewise
     * @throws IllegalArgumentException if a speed lies outside the robot's limit
     */
    public void setMotorSpeeds(int left, int right) {
        int max = port.maxSpeed();
        if (left < -max || left > max || right < -max || right > max) {
            throw new IllegalArgumentException("setMotorSpeeds(" + left + ", " + right
                    + "): each speed must lie in -" + max + ".." + max + " speed units (1 unit is about "
                    + unit(port.mmPerSecondPerUnit()) + " mm/s); clamp the value before calling");
        }
        port.setSpeeds(left, right);
    }

    /** @return the largest speed magnitude the robot accepts, speed units (127 on a Khepera) */
    public int getMaxSpeed() {
        return port.maxSpeed();
    }

    /** @return the wheel speed of one speed unit, mm/s (about 8 on a Khepera) */
    public double getMmPerSecondPerUnit() {
        return port.mmPerSecondPerUnit();
    }

    private static String unit(double mmPerS) {
        return mmPerS == Math.rint(mmPerS) ? Long.toString((long) mmPerS) : Double.toString(mmPerS);
    }

    /** @return the left wheel speed last asked for, speed units */
    public int getLeftSpeed() {
        return port.leftSpeed();
    }

    /** @return the right wheel speed last asked for, speed units */
    public int getRightSpeed() {
        return port.rightSpeed();
    }

    /** @return the left wheel position counter, pulses (≈ 0.08 mm each) */
    public int getLeftPosition() {
        return port.leftPosition();
    }

    /** @return the right wheel position counter, pulses (≈ 0.08 mm each) */
    public int getRightPosition() {
        return port.rightPosition();
    }

    /**
     * Set both position counters (the protocol's {@code G} command).
     *
     * @param left new left counter, pulses
     * @param right new right counter, pulses
     */
    public void setPositions(int left, int right) {
        port.setPositions(left, right);
    }

    /** Reset both position counters to zero. */
    public void resetPositions() {
        port.setPositions(0, 0);
    }
}
