package org.kheperasim.controllers;

/**
 * Dead reckoning from the wheel encoders: where the robot is and which way it faces, in the frame of
 * the pose it was given at the start. Call {@link #update(int, int)} with the two position counters
 * every time the controller reads them (as often as it likes: each call adds the travel since the
 * last one).
 *
 * <p>The Khepera counts 0.08 mm of wheel travel per pulse, and its wheels are 53 mm apart. A short
 * step of the two wheels is taken as an arc: the robot turns by the difference of the wheels' travel
 * over the wheel base and moves by their mean along the heading halfway through the turn. The
 * simulator's encoders count what the wheels really did, so this stays true for a long time there;
 * on the real robot wheels slip, and the estimate drifts a few percent of the distance travelled.
 */
public final class Odometry {
    /** Wheel travel per encoder pulse, mm. */
    public static final double MM_PER_PULSE = 0.08;
    /** Distance between the wheels, mm. */
    public static final double WHEEL_BASE_MM = 53.0;

    private double x;
    private double y;
    private double heading;
    private int lastLeft;
    private int lastRight;
    private double lastStep;

    /**
     * @param x where the robot starts, mm
     * @param y where the robot starts, mm
     * @param heading which way it faces, radians (0 = along x, counter-clockwise)
     * @param left the left position counter now
     * @param right the right position counter now
     */
    public Odometry(double x, double y, double heading, int left, int right) {
        this.x = x;
        this.y = y;
        this.heading = heading;
        this.lastLeft = left;
        this.lastRight = right;
    }

    /**
     * Add the travel since the last update.
     *
     * @param left the left position counter, pulses
     * @param right the right position counter, pulses
     */
    public void update(int left, int right) {
        double dl = (left - lastLeft) * MM_PER_PULSE;
        double dr = (right - lastRight) * MM_PER_PULSE;
        lastLeft = left;
        lastRight = right;
        double turn = (dr - dl) / WHEEL_BASE_MM;
        double mean = (dl + dr) / 2;
        x += mean * StrictMath.cos(heading + turn / 2);
        y += mean * StrictMath.sin(heading + turn / 2);
        heading = wrap(heading + turn);
        lastStep = StrictMath.abs(dl) + StrictMath.abs(dr);
    }

    /** @return the estimated x, mm */
    public double x() {
        return x;
    }

    /** @return the estimated y, mm */
    public double y() {
        return y;
    }

    /** @return the heading, radians in (-pi, pi] */
    public double heading() {
        return heading;
    }

    /** @return how far the two wheels travelled together in the last update, mm */
    public double lastStep() {
        return lastStep;
    }

    /** @return the distance from here to (tx, ty), mm */
    public double distanceTo(double tx, double ty) {
        return StrictMath.hypot(tx - x, ty - y);
    }

    /** @return the turn from the heading to the direction of (tx, ty), radians in (-pi, pi] */
    public double bearingTo(double tx, double ty) {
        return wrap(StrictMath.atan2(ty - y, tx - x) - heading);
    }

    /** @return the angle a, brought into (-pi, pi] */
    public static double wrap(double a) {
        double w = a % (2 * StrictMath.PI);
        if (w > StrictMath.PI) {
            return w - 2 * StrictMath.PI;
        }
        if (w <= -StrictMath.PI) {
            return w + 2 * StrictMath.PI;
        }
        return w;
    }
}
