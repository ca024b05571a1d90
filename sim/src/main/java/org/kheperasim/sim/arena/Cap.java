package org.kheperasim.sim.arena;

/**
 * A bottle cap: a small disc on the floor that the robot can push or pick up.
 *
 * @param x      centre, mm
 * @param y      centre, mm
 * @param radius mm, greater than 0 (a soda bottle cap is about 9 mm)
 */
public record Cap(double x, double y, double radius) {

    /** Radius of a cap when the file does not give one, mm. */
    public static final double DEFAULT_RADIUS = 9;

    /** @throws IllegalArgumentException if a number is not finite or the radius is not positive */
    public Cap {
        x = Numbers.finite("cap x", x);
        y = Numbers.finite("cap y", y);
        radius = Numbers.positive("cap radius", radius, "mm");
    }

    /**
     * A cap of the default radius.
     *
     * @param x centre, mm
     * @param y centre, mm
     */
    public Cap(double x, double y) {
        this(x, y, DEFAULT_RADIUS);
    }
}
