package org.kheperasim.sim.engine.model;

/**
 * How long a WSU controller's pause between two {@code doWork()} calls lasts ({@code wsu.loopTiming}).
 *
 * <p>{@code exact} (the default): what the controller asks, 20 ms of robot time. {@code desktop}: as in
 * the original simulator, whose controller thread slept on the desktop's clock while its engine thread
 * drove the robot on: the pause lasts the 20 ms asked plus a delay drawn from the distribution measured
 * in the original (v7.3 of the WSU Khepera Suite run under Xvfb on OpenJDK 17 with a probe controller
 * that read the turret and the eight proximity sensors and set the speeds each loop; 600 loops,
 * December 2026): loop periods of 20.04 ms at least, 20.10 at the median, 21.05 at the 90th percentile,
 * 22.75 at the 95th, 51.4 at the 99th and 224 at most. Controllers that count loops instead of reading
 * the clock (open-loop turns of so many steps) end those moves at different places from run to run
 * there, and here from seed to seed.
 */
public final class LoopTiming {
    /** The setting's key. */
    public static final String KEY = "wsu.loopTiming";
    /** Every pause as long as asked. */
    public static final String EXACT = "exact";
    /** The original's pauses, as measured. */
    public static final String DESKTOP = "desktop";

    /** Cumulative probabilities of the measured quantiles. */
    private static final double[] P = {0, 0.05, 0.10, 0.25, 0.50, 0.75, 0.90, 0.95, 0.99, 1};
    /** The loop period beyond the 20 ms asked at those quantiles, ms (the original's p0..p100 less 20). */
    private static final double[] EXTRA_MS = {0.04, 0.08, 0.08, 0.09, 0.10, 0.14, 1.05, 2.75, 31.38, 204.15};

    private LoopTiming() {
    }

    /** @param settings a robot's settings @return true when its pauses follow the original's desktop */
    public static boolean desktop(Settings settings) {
        return DESKTOP.equals(settings.raw(KEY));
    }

    /**
     * The delay added to a pause, read off the measured distribution (linear between its quantiles).
     *
     * @param u a uniform draw in [0, 1)
     * @return nanoseconds to add to the pause
     */
    public static long extraNanos(double u) {
        int i = 1;
        while (i < P.length - 1 && u > P[i]) {
            i++;
        }
        double ms = EXTRA_MS[i - 1] + (EXTRA_MS[i] - EXTRA_MS[i - 1]) * (u - P[i - 1]) / (P[i] - P[i - 1]);
        return StrictMath.round(ms * 1e6);
    }
}
