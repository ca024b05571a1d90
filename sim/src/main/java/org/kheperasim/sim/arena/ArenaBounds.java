package org.kheperasim.sim.arena;

import java.util.List;
import java.util.Locale;

/** Whole-arena checks of a parse: everything lies on the floor, and the walls do not bury it. */
final class ArenaBounds {
    private final String source;
    private final double width;
    private final double height;

    ArenaBounds(String source, double width, double height) {
        this.source = source;
        this.width = width;
        this.height = height;
    }

    /** Refuses a point off the floor, naming its line. */
    void inside(String what, double x, double y, int line) {
        if (x < 0 || y < 0 || x > width || y > height) {
            String w = Numbers.brief(width);
            String h = Numbers.brief(height);
            throw new ArenaFormatException(source, line, what + " at (" + Numbers.brief(x) + ", " + Numbers.brief(y)
                    + ") lies outside the " + w + " x " + h + " mm arena; keep x within 0.." + w
                    + " and y within 0.." + h);
        }
    }

    /**
     * Refuses walls whose areas (length x thickness) add up to more than
     * {@link ArenaLimits#MAX_WALL_AREA_RATIO} times the floor: drawing them would take too long.
     */
    void wallArea(List<Wall> walls, List<Integer> wallLines) {
        double floor = width * height;
        double total = 0;
        for (int i = 0; i < walls.size(); i++) {
            Wall w = walls.get(i);
            total += (StrictMath.hypot(w.x2() - w.x1(), w.y2() - w.y1()) + w.thickness()) * w.thickness();
            if (total > ArenaLimits.MAX_WALL_AREA_RATIO * floor) {
                throw new ArenaFormatException(source, wallLines.get(i), String.format(Locale.ROOT, "the walls up to"
                        + " this one cover %.1f times the floor's area (each wall counts (length + thickness) x"
                        + " thickness); at most %s times is allowed, so remove walls that overlap or make them thinner",
                        total / floor, Numbers.brief(ArenaLimits.MAX_WALL_AREA_RATIO)));
            }
        }
    }
}
