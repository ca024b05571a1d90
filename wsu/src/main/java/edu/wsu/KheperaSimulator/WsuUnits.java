package edu.wsu.KheperaSimulator;

/**
 * How the WSU API's numbers map onto the Khepera's units.
 *
 * <p><b>Speed.</b> A WSU controller sets each wheel to a speed of −9..9. The original simulator's
 * motion per unit was not calibrated, but its remote-robot program sent a controller's speeds to the
 * real robot unchanged ({@code D,left,right}), so on the robot one WSU unit was one Khepera speed
 * unit (one encoder pulse per 10 ms, about 8 mm/s). We keep that: WSU speed {@code s} is Khepera
 * speed {@code s}, so 9 is about 72 mm/s, in the simulator and on the robot alike.
 *
 * <p><b>Wheel positions</b> are the Khepera's position counters in encoder pulses (about 0.08 mm of
 * wheel travel each), counted from 0 at the start of each run, in a {@code long} that does not wrap.
 */
final class WsuUnits {
    /** The slowest speed a WSU controller may ask for (full speed backwards), WSU units. */
    static final int MIN_SPEED = -9;
    /** The fastest speed a WSU controller may ask for, WSU units. */
    static final int MAX_SPEED = 9;
    /** A speed outside the range: the wheel it is given for keeps its speed. */
    static final int INVALID_SPEED = Integer.MIN_VALUE;
    /** Khepera speed units (≈ 8 mm/s each) per WSU speed unit. */
    static final int KHEPERA_SPEED_PER_WSU_SPEED = 1;

    private WsuUnits() {
    }

    /** @param wsu a wheel speed, WSU units @return whether the original accepted it (−9..9) */
    static boolean validSpeed(int wsu) {
        return wsu >= MIN_SPEED && wsu <= MAX_SPEED;
    }

    /** @param wsu a valid wheel speed, −9..9 WSU units @return the same speed in Khepera speed units (≈ 8 mm/s) */
    static int toKheperaSpeed(int wsu) {
        return wsu * KHEPERA_SPEED_PER_WSU_SPEED;
    }
}
