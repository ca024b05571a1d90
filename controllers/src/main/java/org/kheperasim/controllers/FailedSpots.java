package org.kheperasim.controllers;

/**
 * Spots where an approach to a cap failed (a cap jammed in a corner, a wall end taken for a cap):
 * after two failures a spot is left alone, so the controller cannot livelock there.
 */
final class FailedSpots {
    private static final double NEAR_MM = 40;
    private final double[] xs = new double[32];
    private final double[] ys = new double[32];
    private final int[] tries = new int[32];
    private int count;

    /** Count a failed approach to what was seen near (x, y). */
    void note(double x, double y) {
        for (int i = 0; i < count; i++) {
            if (StrictMath.hypot(x - xs[i], y - ys[i]) < NEAR_MM) {
                tries[i]++;
                return;
            }
        }
        if (count < xs.length) {
            xs[count] = x;
            ys[count] = y;
            tries[count++] = 1;
        }
    }

    /** @return true when what is seen near (x, y) has failed twice already */
    boolean givenUp(double x, double y) {
        for (int i = 0; i < count; i++) {
            if (tries[i] >= 2 && StrictMath.hypot(x - xs[i], y - ys[i]) < NEAR_MM) {
                return true;
            }
        }
        return false;
    }
}
