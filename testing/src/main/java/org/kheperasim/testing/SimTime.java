package org.kheperasim.testing;

import java.util.Locale;

/**
 * A span of simulated time, or an instant of a run counted from its start: the simulator's clock,
 * never the wall clock. A run of 120 simulated seconds usually takes well under a second of real time.
 *
 * <p>Written in a test with {@link KheperaAssertions#seconds(double)}, {@link KheperaAssertions#millis(long)} or
 * {@link KheperaAssertions#minutes(double)}; shown as {@code 41.300 s}.
 *
 * @param nanos the time, nanoseconds (the simulator's clock counts whole milliseconds, and an API call costs
 *     a few microseconds of it)
 */
public record SimTime(long nanos) implements Comparable<SimTime> {
    /** The start of a run. */
    public static final SimTime ZERO = new SimTime(0);

    /**
     * @param nanos the time, nanoseconds, 0 or more
     * @throws IllegalArgumentException when {@code nanos} is negative
     */
    public SimTime {
        if (nanos < 0) {
            throw new IllegalArgumentException("simulated time " + nanos + " ns is negative; a run's time starts at 0");
        }
    }

    /**
     * @param seconds simulated seconds, 0 or more (a decimal such as {@code 0.25} is fine)
     * @return that time, to the nanosecond
     * @throws IllegalArgumentException when {@code seconds} is negative, infinite or not a number
     */
    public static SimTime ofSeconds(double seconds) {
        if (!(seconds >= 0) || Double.isInfinite(seconds)) {
            throw new IllegalArgumentException("simulated time of " + seconds + " s: give 0 or more seconds");
        }
        return new SimTime(Math.round(seconds * 1e9));
    }

    /**
     * @param millis simulated milliseconds, 0 or more
     * @return that time
     */
    public static SimTime ofMillis(long millis) {
        return new SimTime(Math.multiplyExact(millis, 1_000_000L));
    }

    /** @return this time in seconds */
    public double seconds() {
        return nanos / 1e9;
    }

    /** @return this time in whole milliseconds, rounded down */
    public long millis() {
        return nanos / 1_000_000L;
    }

    /**
     * @param other another time
     * @return true when this time comes strictly before {@code other}
     */
    public boolean isBefore(SimTime other) {
        return nanos < other.nanos;
    }

    /**
     * @param other another time
     * @return true when this time comes strictly after {@code other}
     */
    public boolean isAfter(SimTime other) {
        return nanos > other.nanos;
    }

    /**
     * @param other another time
     * @return this plus {@code other}
     */
    public SimTime plus(SimTime other) {
        return new SimTime(Math.addExact(nanos, other.nanos));
    }

    @Override
    public int compareTo(SimTime other) {
        return Long.compare(nanos, other.nanos);
    }

    /** @return the time as a test's message shows it, e.g. {@code 41.300 s} */
    @Override
    public String toString() {
        return String.format(Locale.ROOT, "%.3f s", seconds());
    }
}
