package org.kheperasim.sim.arena;

/**
 * A fixed wall: a straight segment with a thickness. The solid part is every point within
 * {@code thickness / 2} of the segment (a capsule: flat sides, rounded ends), so walls that meet
 * end to end at the same point join without a gap.
 *
 * @param x1        first end of the centre line, mm
 * @param y1        first end of the centre line, mm
 * @param x2        second end of the centre line, mm
 * @param y2        second end of the centre line, mm
 * @param thickness full thickness, mm, greater than 0
 */
public record Wall(double x1, double y1, double x2, double y2, double thickness) {

    /**
     * @throws IllegalArgumentException if a number is not finite, the thickness is not positive,
     *                                  or both ends are the same point
     */
    public Wall {
        x1 = Numbers.finite("wall x1", x1);
        y1 = Numbers.finite("wall y1", y1);
        x2 = Numbers.finite("wall x2", x2);
        y2 = Numbers.finite("wall y2", y2);
        thickness = Numbers.positive("wall thickness", thickness, "mm");
        if (x1 == x2 && y1 == y2) {
            throw new IllegalArgumentException("wall has both ends at (" + Numbers.brief(x1) + ", "
                    + Numbers.brief(y1) + "); give two different end points");
        }
    }
}
