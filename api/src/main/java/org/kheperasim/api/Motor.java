package org.kheperasim.api;

import org.kheperasim.api.spi.RobotPort;

/**
 * The two wheel motors and their position counters (encoders). A live view.
 *
 * <p>Speeds are in speed units: one unit is one encoder pulse per 10 ms, about 8 mm/s; the robot
 * accepts −127..127. Positions are in pulses, about 0.08 mm of wheel travel each; they stop
 * counting while the robot is blocked, which is how a controller can tell it is stuck.
 */
public final class Motor {
    /** The largest speed magnitude the Khepera accepts, speed units. */
    public static final int MAX_SPEED = 127;

    private final RobotPort port;

    Motor(RobotPort port) {
        this.port = port;
    }

    /**
     * Set both wheel speeds. The command reaches the robot after the serial line's transmission
     * time, as on the real robot.
     *
     * @param left left wheel speed, −127..127 speed units (≈ 8 mm/s each); positive drives forward
     * @param right right wheel speed, −127..127 speed units
     * @throws IllegalArgumentException if a speed lies outside −127..127
     */
    public void setMotorSpeeds(int left, int right) {
        if (left < -MAX_SPEED || left > MAX_SPEED || right < -MAX_SPEED || right > MAX_SPEED) {
            throw new IllegalArgumentException("setMotorSpeeds(" + left + ", " + right
                    + "): each speed must lie in -127..127 speed units (1 unit is about 8 mm/s);"
                    + " clamp the value before calling");
        }
        port.setSpeeds(left, right);
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
