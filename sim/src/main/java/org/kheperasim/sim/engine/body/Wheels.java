package org.kheperasim.sim.engine.body;

import org.kheperasim.sim.engine.model.RobotModel;
import org.kheperasim.sim.engine.model.Ticks;
import org.kheperasim.sim.engine.noise.CounterNoise;
import org.kheperasim.sim.engine.robot.RobotType;

/**
 * The two wheels' speeds: the commanded speeds (units), and the speeds they really turn at (mm/s),
 * with each wheel's calibration and its speed noise, redrawn every noise period of the robot's
 * drive ({@link RobotType.Drive#noisePeriodNanos}).
 */
public final class Wheels {
    private static final double TICK_S = Ticks.NANOS / 1e9;

    /** Wheel speed of one speed unit, mm/s, and the noise period, ns: the robot type's. */
    private final double mmPerUnit;
    /** The distance between the wheels, mm. */
    private final double wheelBase;
    private final long noisePeriod;
    private final double calibrationLeft;
    private final double calibrationRight;
    private final double noiseSigmaLeft;
    private final double noiseSigmaRight;
    private final CounterNoise noiseLeft;
    private final CounterNoise noiseRight;
    private int speedLeft;
    private int speedRight;
    private double noiseFactorLeft = 1;
    private double noiseFactorRight = 1;
    private long nextNoiseNanos;
    /** What the wheels turn at now, mm/s at the rim. */
    private double left;
    private double right;

    Wheels(RobotType.Drive drive, RobotModel.Motors motors, double readingNoise, double calibrationLeft,
            double calibrationRight, CounterNoise noiseLeft, CounterNoise noiseRight) {
        this.mmPerUnit = drive.mmPerSecondPerUnit();
        this.wheelBase = drive.wheelBaseMm();
        this.noisePeriod = drive.noisePeriodNanos();
        this.calibrationLeft = calibrationLeft;
        this.calibrationRight = calibrationRight;
        this.noiseSigmaLeft = motors.noiseLeft() * readingNoise;
        this.noiseSigmaRight = motors.noiseRight() * readingNoise;
        this.noiseLeft = noiseLeft;
        this.noiseRight = noiseRight;
    }

    /** The wheels take new speeds, units. */
    public void setSpeeds(int left, int right) {
        speedLeft = left;
        speedRight = right;
        refresh();
    }

    /** Redraw the wheels' speed noise when its period has come round; returns when it is next due, ns. */
    public long noiseDue(long now) {
        if (now >= nextNoiseNanos) {
            long period = now / noisePeriod;
            nextNoiseNanos = (period + 1) * noisePeriod;
            if (noiseSigmaLeft > 0 || noiseSigmaRight > 0) {
                noiseFactorLeft = 1 + noiseSigmaLeft * noiseLeft.gaussian(period);
                noiseFactorRight = 1 + noiseSigmaRight * noiseRight.gaussian(period);
                refresh();
            }
        }
        return nextNoiseNanos;
    }

    private void refresh() {
        left = speedLeft * mmPerUnit * calibrationLeft * noiseFactorLeft;
        right = speedRight * mmPerUnit * calibrationRight * noiseFactorRight;
    }

    /** @return the centre's path length over {@code ticks} ticks at the present speeds (signed), mm */
    public double common(long ticks) {
        double dt = ticks * TICK_S;
        return (left * dt + right * dt) * 0.5;
    }

    /** @return the body's turn over {@code ticks} ticks at the present speeds, rad */
    public double turn(long ticks) {
        double dt = ticks * TICK_S;
        return (right * dt - left * dt) / wheelBase;
    }

    /** @return half the difference of the wheels' travel over {@code ticks} ticks (right less left), mm */
    public double diff(long ticks) {
        return (right - left) * ticks * TICK_S * 0.5;
    }

    /** @return true when both wheels stand still */
    public boolean still() {
        return speedLeft == 0 && speedRight == 0;
    }

    /** @return how far the centre travels in one tick at most, mm (the arc is no shorter than the chord) */
    public double travelPerTickMm() {
        return StrictMath.abs(left + right) * 0.5 * TICK_S;
    }

    /** @return the left wheel's speed now, mm/s */
    double left() {
        return left;
    }

    /** @return the right wheel's speed now, mm/s */
    double right() {
        return right;
    }

    /** @return the left wheel's commanded speed, units */
    public int speedLeft() {
        return speedLeft;
    }

    /** @return the right wheel's commanded speed, units */
    public int speedRight() {
        return speedRight;
    }
}
