package org.kheperasim.sim.engine.body;

/**
 * What the body's moves count: each wheel encoder's exact travel in pulses (the robot's counters
 * are their floor, {@link DriveBody#pulses}), and how far the centre has travelled.
 */
final class Odometry {
    private final double mmPerPulse;
    private double left;
    private double right;
    private double distance;

    Odometry(double mmPerPulse) {
        this.mmPerPulse = mmPerPulse;
    }

    /**
     * Count a move whose centre drove {@code common} mm along its arc, of which only {@code fraction}
     * was travelled, while the wheels turned {@code diff} mm each the other way (the turn counts whole).
     */
    void count(double common, double diff, double fraction) {
        double moved = common * fraction;
        left += (moved - diff) / mmPerPulse;
        right += (moved + diff) / mmPerPulse;
        distance += StrictMath.abs(moved);
    }

    /** The counters after a move of {@code common}, {@code diff} mm, without counting it: into {@code out[4, 5]}. */
    void preview(double common, double diff, double[] out) {
        out[4] = left + (common - diff) / mmPerPulse;
        out[5] = right + (common + diff) / mmPerPulse;
    }

    /** The counters read {@code l}, {@code r} pulses from now on. */
    void set(int l, int r) {
        left = l;
        right = r;
    }

    double left() {
        return left;
    }

    double right() {
        return right;
    }

    double distanceMm() {
        return distance;
    }
}
