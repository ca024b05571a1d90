package org.kheperasim.sim.arena;

/**
 * Draws a wall onto an {@link OccupancyGrid}: the cells whose centre lies within half the
 * thickness of the wall's centre line, plus every cell the centre line passes through, so that a
 * wall thinner than a cell still leaves no gap. Only onto floor.
 *
 * <p>Row by row, only the cells near the wall's cross-section of that row are tested, so a wall
 * costs about its own cells plus one step per row, never its bounding box: a long slanted wall
 * across a large arena is as cheap as its area. Which cells are painted is decided by the same
 * exact test as always, so the grid is the same cell for cell.
 */
final class WallPainter {

    private static final double CELL = OccupancyGrid.CELL_MM;

    private WallPainter() {
    }

    static void paint(OccupancyGrid g, Wall w) {
        double half = w.thickness() / 2;
        int c0 = Math.max(0, g.col(Math.min(w.x1(), w.x2()) - half));
        int c1 = Math.min(g.cols() - 1, g.col(Math.max(w.x1(), w.x2()) + half));
        int r0 = Math.max(0, g.row(Math.min(w.y1(), w.y2()) - half));
        int r1 = Math.min(g.rows() - 1, g.row(Math.max(w.y1(), w.y2()) + half));
        double[] span = new double[2];
        for (int r = r0; r <= r1; r++) {
            double y = g.cellCentreY(r);
            // One cell of slack around the span makes it a superset despite rounding.
            if (!rowSpan(w, y, half + CELL, span)) {
                continue;
            }
            int from = Math.max(c0, g.col(span[0]) - 1);
            int to = Math.min(c1, g.col(span[1]) + 1);
            for (int c = from; c <= to; c++) {
                if (distanceToSegment(g.cellCentreX(c), y, w) <= half) {
                    g.paintFloor(c, r, OccupancyGrid.WALL);
                }
            }
        }
        paintCentreLine(g, w);
    }

    /**
     * Where the horizontal line at {@code y} crosses the capsule of radius {@code reach} around the
     * wall's centre line (a convex shape, so one interval): the union of the crossings of its two
     * end discs and of the band between them.
     *
     * @param span receives the interval's ends, mm
     * @return false when the line misses the capsule
     */
    static boolean rowSpan(Wall w, double y, double reach, double[] span) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (int end = 0; end < 2; end++) {
            double ex = end == 0 ? w.x1() : w.x2();
            double dy = y - (end == 0 ? w.y1() : w.y2());
            if (Math.abs(dy) <= reach) {
                double dx = Math.sqrt(reach * reach - dy * dy);
                lo = Math.min(lo, ex - dx);
                hi = Math.max(hi, ex + dx);
            }
        }
        // The band: 0 <= u vx + oy vy <= len² along the wall and |u vy - oy vx| <= reach len across
        // it, where u = x - x1.
        double vx = w.x2() - w.x1();
        double vy = w.y2() - w.y1();
        double len = Math.sqrt(vx * vx + vy * vy);
        double oy = y - w.y1();
        double a = Double.NEGATIVE_INFINITY;
        double b = Double.POSITIVE_INFINITY;
        double c = oy * vy;
        if (vx == 0) {
            if (c < 0 || c > len * len) {
                a = Double.POSITIVE_INFINITY;
            }
        } else {
            double u1 = -c / vx;
            double u2 = (len * len - c) / vx;
            a = Math.min(u1, u2);
            b = Math.max(u1, u2);
        }
        c = -oy * vx;
        if (vy == 0) {
            if (Math.abs(c) > reach * len) {
                a = Double.POSITIVE_INFINITY;
            }
        } else {
            double u1 = (-reach * len - c) / vy;
            double u2 = (reach * len - c) / vy;
            a = Math.max(a, Math.min(u1, u2));
            b = Math.min(b, Math.max(u1, u2));
        }
        if (a <= b) {
            lo = Math.min(lo, w.x1() + a);
            hi = Math.max(hi, w.x1() + b);
        }
        span[0] = lo;
        span[1] = hi;
        return lo <= hi;
    }

    /** Paints every cell the wall's centre line passes through, column strip by column strip. */
    private static void paintCentreLine(OccupancyGrid g, Wall w) {
        boolean forward = w.x1() <= w.x2();
        double xa = forward ? w.x1() : w.x2();
        double ya = forward ? w.y1() : w.y2();
        double xb = forward ? w.x2() : w.x1();
        double yb = forward ? w.y2() : w.y1();
        int c0 = Math.max(0, g.col(xa));
        int c1 = Math.min(g.cols() - 1, g.col(xb));
        for (int c = c0; c <= c1; c++) {
            double ys;
            double ye;
            if (xa == xb) {
                ys = ya;
                ye = yb;
            } else {
                double slope = (yb - ya) / (xb - xa);
                ys = ya + slope * (Math.max(xa, c * CELL) - xa);
                ye = ya + slope * (Math.min(xb, (c + 1) * CELL) - xa);
            }
            int r0 = Math.max(0, g.row(Math.min(ys, ye)));
            int r1 = Math.min(g.rows() - 1, g.row(Math.max(ys, ye)));
            for (int r = r0; r <= r1; r++) {
                g.paintFloor(c, r, OccupancyGrid.WALL);
            }
        }
    }

    /** Distance from a point to the wall's centre-line segment, mm. */
    static double distanceToSegment(double px, double py, Wall w) {
        double vx = w.x2() - w.x1();
        double vy = w.y2() - w.y1();
        double t = ((px - w.x1()) * vx + (py - w.y1()) * vy) / (vx * vx + vy * vy);
        t = Math.max(0, Math.min(1, t));
        double dx = px - (w.x1() + t * vx);
        double dy = py - (w.y1() + t * vy);
        return Math.sqrt(dx * dx + dy * dy);
    }
}
