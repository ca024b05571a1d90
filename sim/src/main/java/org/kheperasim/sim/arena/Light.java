package org.kheperasim.sim.arena;

/**
 * A lamp fixed to the floor. Its body is a disc the robot cannot enter; it lights the floor up
 * to {@code range} mm away, all around or in a cone.
 *
 * @param x            centre, mm
 * @param y            centre, mm
 * @param radius       radius of the lamp's body, mm, greater than 0
 * @param range        how far the lamp shines, mm from its centre, greater than 0
 * @param intensity    relative brightness, 0 or more; 1 is the lab lamp the sensor model is
 *                     calibrated for
 * @param directionDeg centre of the cone, degrees counter-clockwise from +x; only meaningful
 *                     when the light is {@linkplain #isDirectional() directional}
 * @param spreadDeg    full width of the cone, degrees, greater than 0 and at most 360;
 *                     360 means the lamp shines all around
 */
public record Light(double x, double y, double radius, double range, double intensity,
                    double directionDeg, double spreadDeg) {

    /** Body radius of a lamp when the file does not give one, mm. */
    public static final double DEFAULT_RADIUS = 6;
    /** Range of a lamp when the file does not give one, mm. */
    public static final double DEFAULT_RANGE = 400;
    /** Intensity of a lamp when the file does not give one. */
    public static final double DEFAULT_INTENSITY = 1;
    /** Cone direction when the file does not give one, degrees. */
    public static final double DEFAULT_DIRECTION = 0;
    /** Cone width when the file does not give one, degrees: all around. */
    public static final double DEFAULT_SPREAD = 360;

    /**
     * @throws IllegalArgumentException if a number is not finite, the radius or range is not
     *                                  positive, the intensity is negative, or the spread is not
     *                                  in (0, 360]
     */
    public Light {
        x = Numbers.finite("light x", x);
        y = Numbers.finite("light y", y);
        radius = Numbers.positive("light radius", radius, "mm");
        range = Numbers.positive("light range", range, "mm");
        intensity = Numbers.finite("light intensity", intensity);
        if (intensity < 0) {
            throw new IllegalArgumentException("light intensity is " + Numbers.brief(intensity)
                    + "; give 0 or more (1 is the standard lamp)");
        }
        directionDeg = Numbers.finite("light direction", directionDeg);
        spreadDeg = Numbers.finite("light spread", spreadDeg);
        if (!(spreadDeg > 0 && spreadDeg <= 360)) {
            throw new IllegalArgumentException("light spread is " + Numbers.brief(spreadDeg)
                    + "; give a cone width in degrees greater than 0 and at most 360 (360 = all around)");
        }
    }

    /**
     * An all-around lamp with the default body radius, range and intensity.
     *
     * @param x centre, mm
     * @param y centre, mm
     */
    public Light(double x, double y) {
        this(x, y, DEFAULT_RADIUS, DEFAULT_RANGE, DEFAULT_INTENSITY, DEFAULT_DIRECTION, DEFAULT_SPREAD);
    }

    /** @return true if the lamp shines in a cone narrower than 360 degrees */
    public boolean isDirectional() {
        return spreadDeg < 360;
    }

    /**
     * Whether a point on the floor is within this lamp's range and inside its cone (obstacles
     * are not considered; the occupancy grid answers that).
     *
     * @param px point, mm
     * @param py point, mm
     * @return true if the point is at most {@code range} mm from the centre and, for a
     *         directional lamp, at most {@code spreadDeg / 2} degrees off its direction
     */
    public boolean shinesOn(double px, double py) {
        double dx = px - x;
        double dy = py - y;
        double dist2 = dx * dx + dy * dy;
        if (dist2 > range * range) {
            return false;
        }
        if (!isDirectional() || dist2 == 0) {
            return true;
        }
        double off = StrictMath.toDegrees(StrictMath.atan2(dy, dx)) - directionDeg;
        off = off - 360 * StrictMath.floor((off + 180) / 360);
        return StrictMath.abs(off) <= spreadDeg / 2;
    }
}
