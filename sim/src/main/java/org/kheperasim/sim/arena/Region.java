package org.kheperasim.sim.arena;

import java.util.regex.Pattern;

/**
 * A named axis-aligned rectangle of the floor, used to ask where a robot is ("did it reach the
 * goal?"). The corners are normalised so that {@code x1 < x2} and {@code y1 < y2}.
 *
 * @param name unique identifier of letters, digits, {@code _} and {@code -}
 * @param x1   left edge, mm
 * @param y1   bottom edge, mm
 * @param x2   right edge, mm
 * @param y2   top edge, mm
 */
public record Region(String name, double x1, double y1, double x2, double y2) {

    /** What a region (or arena) name may contain. */
    static final Pattern NAME = Pattern.compile("[A-Za-z0-9_-]+");

    /**
     * @throws IllegalArgumentException if the name is not an identifier, a number is not finite,
     *                                  or the rectangle has no width or no height
     */
    public Region {
        if (name == null || !NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("region name '" + name
                    + "' is not allowed; use letters, digits, '_' and '-' only");
        }
        x1 = Numbers.finite("region x1", x1);
        y1 = Numbers.finite("region y1", y1);
        x2 = Numbers.finite("region x2", x2);
        y2 = Numbers.finite("region y2", y2);
        if (x1 > x2) {
            double t = x1;
            x1 = x2;
            x2 = t;
        }
        if (y1 > y2) {
            double t = y1;
            y1 = y2;
            y2 = t;
        }
        if (x1 == x2 || y1 == y2) {
            throw new IllegalArgumentException("region '" + name
                    + "' has no area; give corners that differ in both x and y");
        }
    }

    /**
     * @param x point, mm
     * @param y point, mm
     * @return true if the point lies inside the rectangle or on its edge
     */
    public boolean contains(double x, double y) {
        return x >= x1 && x <= x2 && y >= y1 && y <= y2;
    }
}
