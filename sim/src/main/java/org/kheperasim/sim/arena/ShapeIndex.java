package org.kheperasim.sim.arena;

import java.util.Arrays;
import java.util.List;

/**
 * The arena's fixed obstacles as the shapes the arena file gives them, for beams cast against
 * them exactly: every wall a capsule (the points within half its thickness of its centre line),
 * every lamp's body a disc, and the floor's edge, where the occupancy grid ends (the world ends in
 * a wall there, as on the grid). Shapes are numbered walls first, then lamps, in arena order.
 *
 * <p>Two look-ups make a cast cheap: buckets of {@value #BUCKET_MM} mm listing the shapes that
 * reach into each ({@link #gather}), and a lattice of {@value #LATTICE_MM} mm holding, for each of
 * its cells, a lower bound of the distance from any point of the cell to the nearest shape or edge
 * ({@link #clearBelow}), so that a disc far from everything is proven empty by one read.
 *
 * <p>Immutable: a run shares it with every other run of the same walls and lamps.
 */
public final class ShapeIndex {
    /** Side of a bucket, mm. */
    static final double BUCKET_MM = 64;
    /** Side of a cell of the clearance lattice, mm. */
    static final double LATTICE_MM = 16;
    /** Clearances are worked out only this far, mm: a bound of this is "at least this". */
    private static final double CAP_MM = 256;
    /** Allowance for rounding in the bounds, mm (a nanometre). */
    private static final double SLACK_MM = 1e-6;

    private final int count;
    private final int walls;
    /** Shape k: centre line from (ax, ay), unit direction (ux, uy), length len, radius rho. */
    private final double[] ax;
    private final double[] ay;
    private final double[] ux;
    private final double[] uy;
    private final double[] len;
    private final double[] rho;
    /** The floor's extent: the grid's, x in [0, edgeX) and y in [0, edgeY). */
    private final double edgeX;
    private final double edgeY;
    private final int bucketCols;
    private final int bucketRows;
    /** Bucket b's shapes are {@code items[first[b] .. first[b + 1])}, in shape order. */
    private final int[] first;
    private final int[] items;
    private final int latticeCols;
    private final int latticeRows;
    private final double[] clear;

    /**
     * @param arena the arena (its walls and lamps; caps move, and are not here)
     * @param grid its occupancy grid, whose extent is the floor's
     */
    public ShapeIndex(Arena arena, OccupancyGrid grid) {
        List<Wall> ws = arena.walls();
        List<Light> ls = arena.lights();
        walls = ws.size();
        count = walls + ls.size();
        ax = new double[count];
        ay = new double[count];
        ux = new double[count];
        uy = new double[count];
        len = new double[count];
        rho = new double[count];
        for (int k = 0; k < walls; k++) {
            Wall w = ws.get(k);
            double vx = w.x2() - w.x1();
            double vy = w.y2() - w.y1();
            double l = StrictMath.sqrt(vx * vx + vy * vy);
            ax[k] = w.x1();
            ay[k] = w.y1();
            ux[k] = vx / l;
            uy[k] = vy / l;
            len[k] = l;
            rho[k] = w.thickness() / 2;
        }
        for (int j = 0; j < ls.size(); j++) {
            Light l = ls.get(j);
            int k = walls + j;
            ax[k] = l.x();
            ay[k] = l.y();
            ux[k] = 1;
            uy[k] = 0;
            len[k] = 0;
            rho[k] = l.radius();
        }
        edgeX = grid.cols() * OccupancyGrid.CELL_MM;
        edgeY = grid.rows() * OccupancyGrid.CELL_MM;
        bucketCols = cells(edgeX, BUCKET_MM);
        bucketRows = cells(edgeY, BUCKET_MM);
        first = new int[bucketCols * bucketRows + 1];
        items = fillBuckets();
        latticeCols = cells(edgeX, LATTICE_MM);
        latticeRows = cells(edgeY, LATTICE_MM);
        clear = new double[latticeCols * latticeRows];
        fillLattice();
    }

    private static int cells(double extent, double side) {
        return StrictMath.max(1, (int) StrictMath.ceil(extent / side));
    }

    /** Counts, then lists, each shape in every bucket whose square it may reach into. */
    private int[] fillBuckets() {
        double halfDiag = BUCKET_MM * StrictMath.sqrt(0.5);
        int[] counts = new int[first.length];
        for (int pass = 0; pass < 2; pass++) {
            int[] at = pass == 0 ? null : Arrays.copyOf(first, first.length - 1);
            int[] out = pass == 0 ? null : new int[first[first.length - 1]];
            for (int k = 0; k < count; k++) {
                int[] box = box(k, rho[k] + BUCKET_MM, BUCKET_MM, bucketCols, bucketRows);
                for (int r = box[2]; r <= box[3]; r++) {
                    for (int c = box[0]; c <= box[1]; c++) {
                        double d = distance(k, (c + 0.5) * BUCKET_MM, (r + 0.5) * BUCKET_MM);
                        if (d > rho[k] + halfDiag + SLACK_MM) {
                            continue;
                        }
                        int b = r * bucketCols + c;
                        if (pass == 0) {
                            counts[b]++;
                        } else {
                            out[at[b]++] = k;
                        }
                    }
                }
            }
            if (pass == 1) {
                return out;
            }
            for (int b = 0; b < counts.length - 1; b++) {
                first[b + 1] = first[b] + counts[b];
            }
        }
        throw new AssertionError();
    }

    /** Each lattice cell's bound: the nearest shape's or edge's distance from its centre, less half its diagonal. */
    private void fillLattice() {
        double halfDiag = LATTICE_MM * StrictMath.sqrt(0.5) + SLACK_MM;
        for (int r = 0; r < latticeRows; r++) {
            double y = (r + 0.5) * LATTICE_MM;
            for (int c = 0; c < latticeCols; c++) {
                double x = (c + 0.5) * LATTICE_MM;
                double edge = StrictMath.min(StrictMath.min(x, edgeX - x), StrictMath.min(y, edgeY - y));
                clear[r * latticeCols + c] = StrictMath.min(CAP_MM, edge) - halfDiag;
            }
        }
        for (int k = 0; k < count; k++) {
            int[] box = box(k, rho[k] + CAP_MM + LATTICE_MM, LATTICE_MM, latticeCols, latticeRows);
            for (int r = box[2]; r <= box[3]; r++) {
                for (int c = box[0]; c <= box[1]; c++) {
                    double d = distance(k, (c + 0.5) * LATTICE_MM, (r + 0.5) * LATTICE_MM) - rho[k] - halfDiag;
                    int i = r * latticeCols + c;
                    if (d < clear[i]) {
                        clear[i] = d;
                    }
                }
            }
        }
    }

    /** The cells of side {@code side} that shape k's centre line, grown by {@code grow}, may touch: c0, c1, r0, r1. */
    private int[] box(int k, double grow, double side, int cols, int rows) {
        double bx = ax[k] + len[k] * ux[k];
        double by = ay[k] + len[k] * uy[k];
        return new int[] {
            clamp((int) StrictMath.floor((StrictMath.min(ax[k], bx) - grow) / side), cols),
            clamp((int) StrictMath.floor((StrictMath.max(ax[k], bx) + grow) / side), cols),
            clamp((int) StrictMath.floor((StrictMath.min(ay[k], by) - grow) / side), rows),
            clamp((int) StrictMath.floor((StrictMath.max(ay[k], by) + grow) / side), rows)};
    }

    private static int clamp(int i, int n) {
        return i < 0 ? 0 : i >= n ? n - 1 : i;
    }

    /** @return how many shapes there are (walls, then lamps) */
    public int count() {
        return count;
    }

    /** @return the grid id of what shape k is: {@link OccupancyGrid#WALL} or {@link OccupancyGrid#LIGHT} */
    public int id(int k) {
        return k < walls ? OccupancyGrid.WALL : OccupancyGrid.LIGHT;
    }

    /**
     * @return a lower bound of the distance from (x, y) to the nearest shape or the floor's edge, mm
     *     (at most a little under {@value #CAP_MM}; not positive off the floor)
     */
    public double clearBelow(double x, double y) {
        if (!(x >= 0 && y >= 0 && x < edgeX && y < edgeY)) {
            return 0;
        }
        int c = StrictMath.min(latticeCols - 1, (int) (x / LATTICE_MM));
        int r = StrictMath.min(latticeRows - 1, (int) (y / LATTICE_MM));
        return clear[r * latticeCols + c];
    }

    /**
     * The shapes that come within {@code radius} of (x, y), each once, in a fixed order.
     *
     * @param out receives their numbers; at least {@link #count()} long
     * @param seen scratch, at least {@link #count()} long: entry k is set to {@code mark} once shape k is looked at
     * @param mark a value no entry of {@code seen} holds yet
     * @return how many
     */
    public int gather(double x, double y, double radius, int[] out, int[] seen, int mark) {
        int c0 = clamp((int) StrictMath.floor((x - radius) / BUCKET_MM), bucketCols);
        int c1 = clamp((int) StrictMath.floor((x + radius) / BUCKET_MM), bucketCols);
        int r0 = clamp((int) StrictMath.floor((y - radius) / BUCKET_MM), bucketRows);
        int r1 = clamp((int) StrictMath.floor((y + radius) / BUCKET_MM), bucketRows);
        int n = 0;
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                int b = r * bucketCols + c;
                for (int i = first[b]; i < first[b + 1]; i++) {
                    int k = items[i];
                    if (seen[k] != mark) {
                        seen[k] = mark;
                        if (distance(k, x, y) - rho[k] <= radius + SLACK_MM) {
                            out[n++] = k;
                        }
                    }
                }
            }
        }
        return n;
    }

    /**
     * @return whether the disc of {@code radius} around (x, y) reaches the floor's edge (or lies off the floor)
     */
    public boolean nearEdge(double x, double y, double radius) {
        return !(x - radius > 0 && y - radius > 0 && x + radius < edgeX && y + radius < edgeY);
    }

    /**
     * Where a beam from (px, py) along the unit vector (rx, ry) leaves the floor.
     *
     * @return the distance, mm: 0 from a point off the floor
     */
    public double edgeAlong(double px, double py, double rx, double ry) {
        if (!(px >= 0 && py >= 0 && px < edgeX && py < edgeY)) {
            return 0;
        }
        double t = Double.POSITIVE_INFINITY;
        if (rx > 0) {
            t = (edgeX - px) / rx;
        } else if (rx < 0) {
            t = -px / rx;
        }
        if (ry > 0) {
            t = StrictMath.min(t, (edgeY - py) / ry);
        } else if (ry < 0) {
            t = StrictMath.min(t, -py / ry);
        }
        return t;
    }

    /** @return the distance from (x, y) to shape k's surface, mm (negative inside it) */
    public double surface(int k, double x, double y) {
        return distance(k, x, y) - rho[k];
    }

    /** @return the distance from (x, y) to shape k's centre line (a point for a lamp), mm */
    double distance(int k, double x, double y) {
        double wx = x - ax[k];
        double wy = y - ay[k];
        double a = wx * ux[k] + wy * uy[k];
        double t = a < 0 ? 0 : a > len[k] ? len[k] : a;
        double qx = wx - t * ux[k];
        double qy = wy - t * uy[k];
        return StrictMath.sqrt(qx * qx + qy * qy);
    }

    /**
     * Where a beam from (px, py) along the unit vector (rx, ry) first meets shape k.
     *
     * @return the distance, mm: 0 from a point inside it, +infinity if it never does
     */
    public double along(int k, double px, double py, double rx, double ry) {
        double ex = ux[k];
        double ey = uy[k];
        double r = rho[k];
        double l = len[k];
        double wx = px - ax[k];
        double wy = py - ay[k];
        double a = wx * ex + wy * ey;
        double t = a < 0 ? 0 : a > l ? l : a;
        double qx = wx - t * ex;
        double qy = wy - t * ey;
        if (qx * qx + qy * qy <= r * r) {
            return 0;
        }
        // Across the centre line (normal (-ey, ex)): from outside the band |h| <= r, the beam enters
        // the capsule where it enters the band, if that is beside the centre line; else by an end.
        double h = wy * ex - wx * ey;
        double s = ry * ex - rx * ey;
        if (h > r && s < 0 || h < -r && s > 0) {
            double d = ((h > 0 ? r : -r) - h) / s;
            double at = a + d * (rx * ex + ry * ey);
            if (at >= 0 && at <= l) {
                return d;
            }
        }
        double d = disc(ax[k] - px, ay[k] - py, r, rx, ry);
        return l == 0 ? d : StrictMath.min(d, disc(ax[k] + l * ex - px, ay[k] + l * ey - py, r, rx, ry));
    }

    /**
     * Where a beam from the origin along the unit vector (rx, ry) first meets the disc of radius
     * {@code r} centred at (wx, wy).
     *
     * @return the distance, mm: 0 from a point inside it, +infinity if it never does
     */
    public static double disc(double wx, double wy, double r, double rx, double ry) {
        double c = wx * wx + wy * wy - r * r;
        if (c <= 0) {
            return 0;
        }
        double b = wx * rx + wy * ry;
        double disc = b * b - c;
        if (b <= 0 || disc < 0) {
            return Double.POSITIVE_INFINITY;
        }
        // c / (b + root) is b - root without the cancellation of a near miss.
        return c / (b + StrictMath.sqrt(disc));
    }
}
