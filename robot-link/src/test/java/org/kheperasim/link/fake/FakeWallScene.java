package org.kheperasim.link.fake;

import java.util.Random;

/**
 * A white wall, a lamp, and a Khepera's true numbers, for the fake robot
 * ({@link FakeKhepera#setScene}): the robot's sensors follow a response the calibration is not
 * told, warped per sensor by a gain and a distance shift drawn from a seed, with reading noise;
 * its wheels travel a true distance per pulse and turn about a true wheel base, both off the
 * nominal 0.08 mm and 53 mm by a few percent (drawn from the same seed).
 *
 * <p>A cap or another robot stands in for the wall at {@link #placeObject}: the same response, times
 * how much it reflects (drawn from the seed too), as the simulator models them.
 *
 * <p>State: the wall's gap from the body's surface, mm, and where it lies, degrees to the robot's
 * right of ahead. The lamp stands straight ahead at {@link #setLampMm}.
 */
public final class FakeWallScene implements FakeKhepera.Scene {
    /** Khepera I sensor poses: x forward, y left, mm; heading degrees counter-clockwise. */
    private static final double[][] POSES = {{10, 24, 90}, {19, 17, 45}, {25, 6, 0}, {25, -6, 0},
        {19, -17, -45}, {10, -24, -90}, {-24, -10, 180}, {-24, 10, 180}};
    private static final double RADIUS_MM = 27.5;

    private final double[] gain = new double[8];
    private final double[] shiftMm = new double[8];
    private final double mmPerPulse;
    private final double wheelBaseMm;
    private final double rightOverLeft;
    private final Random noise;
    private volatile double drift = 1;
    private double gapMm;
    private double objectRightDeg;
    private double lampMm = 1000;
    private double factor = 1;
    private final double capReflectance;
    private final double robotReflectance;

    /** @param seed draws the warps, the wheels' true numbers and the noise */
    public FakeWallScene(long seed) {
        Random r = new Random(seed);
        for (int i = 0; i < 8; i++) {
            gain[i] = 0.75 + 0.5 * r.nextDouble();
            shiftMm[i] = -2 + 4 * r.nextDouble();
        }
        mmPerPulse = 0.08 * (0.95 + 0.1 * r.nextDouble());
        wheelBaseMm = 53 * (0.95 + 0.1 * r.nextDouble());
        rightOverLeft = 0.97 + 0.06 * r.nextDouble();
        noise = new Random(seed + 1);
        Random objects = new Random(seed + 2);
        capReflectance = 0.4 + 0.4 * objects.nextDouble();
        robotReflectance = 0.5 + 0.4 * objects.nextDouble();
    }

    /** @param gap the wall's gap from the body, mm @param rightDeg where it lies, degrees right of ahead */
    public synchronized void place(double gap, double rightDeg) {
        gapMm = gap;
        objectRightDeg = rightDeg;
        factor = 1;
    }

    /** @param gap an object's gap straight ahead, mm @param reflectance how much it reflects, the wall being 1 */
    public synchronized void placeObject(double gap, double reflectance) {
        gapMm = gap;
        objectRightDeg = 0;
        factor = reflectance;
    }

    /** @return how much a cap reflects here, the wall being 1 */
    public double capReflectance() {
        return capReflectance;
    }

    /** @return how much another robot reflects here, the wall being 1 */
    public double robotReflectance() {
        return robotReflectance;
    }

    /** @param mm the lamp's distance straight ahead of the body, mm */
    public synchronized void setLampMm(double mm) {
        lampMm = mm;
    }

    /** @param factor every proximity signal from now on, times this (1.2: the sensors drifted 20 % up) */
    public void drift(double factor) {
        drift = factor;
    }

    /** @return the wall's gap, mm */
    public synchronized double gapMm() {
        return gapMm;
    }

    /** @return where the wall lies, degrees right of ahead */
    public synchronized double objectRightDeg() {
        return objectRightDeg;
    }

    /** @return the true wheel travel per pulse, mm */
    public double mmPerPulse() {
        return mmPerPulse;
    }

    /** @return the true wheel base, mm */
    public double wheelBaseMm() {
        return wheelBaseMm;
    }

    /** @return the right wheel's true travel over the left's at equal commands */
    public double rightOverLeft() {
        return rightOverLeft;
    }

    @Override
    public synchronized void moved(double leftPulses, double rightPulses) {
        double l = leftPulses * mmPerPulse;
        double r = rightPulses * mmPerPulse * rightOverLeft;
        double forward = (l + r) / 2;
        double turnDeg = StrictMath.toDegrees((r - l) / wheelBaseMm);
        gapMm -= forward * StrictMath.cos(StrictMath.toRadians(objectRightDeg + turnDeg / 2));
        objectRightDeg += turnDeg;
    }

    /**
     * @param i a sensor
     * @param gap the wall's gap, mm
     * @param rightDeg where it lies, degrees right of ahead
     * @return the sensor's reading without noise
     */
    public double expected(int i, double gap, double rightDeg) {
        return expected(i, gap, rightDeg, 1);
    }

    /** @return as {@link #expected(int, double, double)}, for an object reflecting {@code reflectance} of the wall */
    public double expected(int i, double gap, double rightDeg, double reflectance) {
        double th = StrictMath.toRadians(rightDeg);
        double ux = StrictMath.cos(th);
        double uy = -StrictMath.sin(th);
        double d = RADIUS_MM + gap - (POSES[i][0] * ux + POSES[i][1] * uy) + shiftMm[i];
        double off = StrictMath.abs(Math.IEEEremainder(-rightDeg - POSES[i][2], 360));
        double lobe = off >= 70 ? 0 : StrictMath.pow(StrictMath.cos(StrictMath.toRadians(off * 90 / 70)), 1.5);
        double along = d <= 0 ? 1.2 : 1.2 * StrictMath.exp(-StrictMath.pow(d / 16, 2));
        return StrictMath.min(1023, 5 + drift * gain[i] * 1023 * StrictMath.min(1.2, along) * lobe * reflectance);
    }

    @Override
    public synchronized int[] proximity() {
        int[] out = new int[8];
        for (int i = 0; i < 8; i++) {
            double v = expected(i, gapMm, objectRightDeg, factor) + 3 * noise.nextGaussian();
            out[i] = (int) StrictMath.max(0, StrictMath.min(1023, StrictMath.rint(v)));
        }
        return out;
    }

    @Override
    public synchronized int[] light() {
        int[] out = new int[8];
        for (int i = 0; i < 8; i++) {
            double facing = StrictMath.max(0, StrictMath.cos(StrictMath.toRadians(POSES[i][2])));
            double v = 480 - 460 * facing / (1 + StrictMath.pow(lampMm / 60, 2)) + 2 * noise.nextGaussian();
            out[i] = (int) StrictMath.max(0, StrictMath.min(1023, StrictMath.rint(v)));
        }
        return out;
    }
}
