package edu.wsu.KheperaSimulator;

/**
 * How the WSU API's numbers map onto the Khepera's units.
 *
 * <p><b>Speed.</b> A WSU controller sets each wheel to a speed of −9..9. The original simulator's
 * motion per unit was not calibrated, but its remote-robot program sent a controller's speeds to the
 * real robot unchanged ({@code D,left,right}), so on the robot one WSU unit was one Khepera speed
 * unit (one encoder pulse per 10 ms, about 8 mm/s). We keep that: WSU speed {@code s} is Khepera
 * speed {@code s}, so 9 is about 72 mm/s, in the simulator and on the robot alike. With the backend's
 * option {@value #SPEED_UNITS} set to {@value #LEGACY} a unit is as fast as the original simulator
 * drew it instead: {@link #LEGACY_SPEED_PER_WSU_SPEED} Khepera units (≈ 30 mm/s), so 5 is ≈ 151 mm/s.
 *
 * <p><b>Wheel positions</b> are the Khepera's position counters in encoder pulses (about 0.08 mm of
 * wheel travel each), counted from 0 at the start of each run, in a {@code long} that does not wrap.
 * With the backend's option {@value #POSITION_UNITS} set to {@value #LEGACY} they count as the original
 * simulator's counter did instead: {@value #LEGACY_COUNTS_PER_DEGREE} counts per degree of a turn on the
 * spot (course code divides by 3 to get degrees), which on the Khepera's 53 mm wheel base is
 * {@link #LEGACY_COUNTS_PER_PULSE} counts per pulse.
 *
 * <p><b>The pose</b> of the later fork's API is in the original's panel: pixels of 2.4384 mm
 * ({@value #PANEL_PX} px = 1219.2 mm, the paper's 4 ft lab), x to the right and y down from the
 * top-left corner, the heading in radians growing clockwise on the screen, 0 facing east (+x).
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

    /** The backend option that chooses the speeds' unit: {@value #KHEPERA} (default) or {@value #LEGACY}. */
    static final String SPEED_UNITS = "wsu.speedUnits";
    /** Speeds in Khepera speed units (≈ 8 mm/s each), as the original's remote-robot program sent them. */
    static final String KHEPERA = "khepera";
    /**
     * Khepera speed units per WSU speed unit with {@value #SPEED_UNITS}={@value #LEGACY}: the original
     * simulator's counter ran about 980 counts a second at speed 5, which at
     * {@link #LEGACY_COUNTS_PER_PULSE} counts per pulse is about 1890 pulses a second, 18.9 Khepera
     * units (pulses per 10 ms) for 5 WSU units: ≈ 3.78 a unit (≈ 30 mm/s).
     */
    static final double LEGACY_SPEED_PER_WSU_SPEED = 980.0 / 5 / 100 / legacyCountsPerPulse();

    /** The backend option that chooses the wheel positions' unit: {@value #PULSES} (default) or {@value #LEGACY}. */
    static final String POSITION_UNITS = "wsu.positionUnits";
    /** Wheel positions in the Khepera's encoder pulses (≈ 0.08 mm each), the same numbers as on the robot. */
    static final String PULSES = "pulses";
    /** Wheel positions counted as the original simulator counted them. */
    static final String LEGACY = "legacy";
    /**
     * The original simulator's counts per degree of a turn on the spot (course code turns by
     * {@code counts / 3} degrees; measured on the original: about 980 counts a second at speed 5,
     * about 3 counts per degree).
     */
    static final double LEGACY_COUNTS_PER_DEGREE = 3;
    /** The Khepera's wheel base, mm. */
    static final double WHEEL_BASE_MM = 53;
    /** Wheel travel per encoder pulse, mm (Khepera User Manual). */
    static final double MM_PER_PULSE = 0.08;
    /**
     * Legacy counts per encoder pulse: {@value #LEGACY_COUNTS_PER_DEGREE} over the pulses a wheel turns per degree on
     * the spot.
     */
    static final double LEGACY_COUNTS_PER_PULSE = legacyCountsPerPulse();
    /** The original's panel, pixels a side. */
    static final int PANEL_PX = 500;
    /** Millimetres per pixel of the original's panel (1219.2 mm / 500 px). */
    static final double MM_PER_PX = 1219.2 / PANEL_PX;
    /** Where the original starts its robot: the centre at (263, 263) px, facing east. */
    static final double START_PX = 263;

    private WsuUnits() {
    }

    /** (The constants it reads are compile-time constants, so it may run before the fields above it are set.) */
    private static double legacyCountsPerPulse() {
        return LEGACY_COUNTS_PER_DEGREE / (WHEEL_BASE_MM / 2 * StrictMath.PI / 180 / MM_PER_PULSE);
    }

    /** @param wsu a wheel speed, WSU units @return whether the original accepted it (−9..9) */
    static boolean validSpeed(int wsu) {
        return wsu >= MIN_SPEED && wsu <= MAX_SPEED;
    }

    /**
     * @param option the backend's {@value #POSITION_UNITS} option, or null
     * @return true for {@value #LEGACY}
     * @throws IllegalArgumentException for a value that is neither unit, naming both
     */
    static boolean legacyPositions(String option) {
        if (option == null || option.equals(PULSES)) {
            return false;
        }
        if (option.equals(LEGACY)) {
            return true;
        }
        throw new IllegalArgumentException(POSITION_UNITS + "=" + option + " is not a unit: use " + PULSES
                + " (the Khepera's encoder pulses, the default) or " + LEGACY + " (the original simulator's counts)");
    }

    /**
     * @param option the backend's {@value #SPEED_UNITS} option, or null
     * @return true for {@value #LEGACY}
     * @throws IllegalArgumentException for a value that is neither unit, naming both
     */
    static boolean legacySpeeds(String option) {
        if (option == null || option.equals(KHEPERA)) {
            return false;
        }
        if (option.equals(LEGACY)) {
            return true;
        }
        throw new IllegalArgumentException(SPEED_UNITS + "=" + option + " is not a unit: use " + KHEPERA
                + " (one Khepera speed unit, about 8 mm/s, the default) or " + LEGACY
                + " (as fast as the original simulator drew it, about 30 mm/s)");
    }

    /** @param wsu a valid wheel speed, −9..9 WSU units @return the same speed in Khepera speed units (≈ 8 mm/s) */
    static int toKheperaSpeed(int wsu) {
        return wsu * KHEPERA_SPEED_PER_WSU_SPEED;
    }

    /**
     * @param wsu a valid wheel speed, −9..9 WSU units
     * @param legacy whether {@value #SPEED_UNITS} is {@value #LEGACY}
     * @return the speed in Khepera speed units: {@code wsu}, or {@code wsu} × {@link #LEGACY_SPEED_PER_WSU_SPEED}
     *     rounded
     */
    static int toKheperaSpeed(int wsu, boolean legacy) {
        return legacy ? (int) StrictMath.round(wsu * LEGACY_SPEED_PER_WSU_SPEED) : toKheperaSpeed(wsu);
    }
}
