package org.kheperasim.sim.engine;

import java.util.Arrays;

/**
 * Where the robots' bodies are, so that they meet each other: a uniform grid of buckets over the
 * arena, each listing the robots whose centre lies in it, so that a robot finds its neighbours
 * without looking at every other robot (contacts do not grow with N²). Every robot is a disc of
 * {@link Khepera#BODY_RADIUS_MM}. Updated whenever a robot moves; read by the robots' contacts,
 * glides and proximity beams, and by the caps (a cap cannot be pushed into a robot).
 */
final class Bodies {
    /** Bucket size: a little more than a body's diameter. */
    static final double CELL_MM = 64;
    private static final double R = Khepera.BODY_RADIUS_MM;

    private final int cols;
    private final int rows;
    private final int[] head;
    private int[] next = new int[0];
    private int[] cellOf = new int[0];
    private double[] x = new double[0];
    private double[] y = new double[0];
    private int count;

    /** @param width the arena's width, mm @param height its height, mm */
    Bodies(double width, double height) {
        cols = StrictMath.max(1, (int) StrictMath.ceil(width / CELL_MM));
        rows = StrictMath.max(1, (int) StrictMath.ceil(height / CELL_MM));
        head = new int[cols * rows];
        Arrays.fill(head, -1);
    }

    /** @return how many robots there are */
    int count() {
        return count;
    }

    double x(int i) {
        return x[i];
    }

    double y(int i) {
        return y[i];
    }

    /** Robot {@code i} (the next index) joins at (px, py). */
    void add(int i, double px, double py) {
        if (i != count) {
            throw new IllegalArgumentException("robots join in order: expected " + count + ", got " + i);
        }
        count++;
        x = Arrays.copyOf(x, count);
        y = Arrays.copyOf(y, count);
        next = Arrays.copyOf(next, count);
        cellOf = Arrays.copyOf(cellOf, count);
        cellOf[i] = -1;
        moved(i, px, py);
    }

    /** Robot {@code i} is now at (px, py). */
    void moved(int i, double px, double py) {
        x[i] = px;
        y[i] = py;
        int cell = cell(px, py);
        if (cell == cellOf[i]) {
            return;
        }
        if (cellOf[i] >= 0) {
            unlink(i);
        }
        next[i] = head[cell];
        head[cell] = i;
        cellOf[i] = cell;
    }

    private void unlink(int i) {
        int c = cellOf[i];
        if (head[c] == i) {
            head[c] = next[i];
            return;
        }
        for (int k = head[c]; k >= 0; k = next[k]) {
            if (next[k] == i) {
                next[k] = next[i];
                return;
            }
        }
    }

    private int cell(double px, double py) {
        int c = StrictMath.min(cols - 1, StrictMath.max(0, (int) (px / CELL_MM)));
        int r = StrictMath.min(rows - 1, StrictMath.max(0, (int) (py / CELL_MM)));
        return r * cols + c;
    }

    /** What {@link #visit} calls for each robot near enough. */
    interface Visitor {
        /** @param k the robot @param dx its centre's x less the point's @param dy likewise y */
        void visit(int k, double dx, double dy);
    }

    /**
     * Call {@code visitor} for every robot but {@code self} whose centre may lie within
     * {@code radius} of (px, py) (the buckets touching that disc), in a fixed order.
     */
    void visit(int self, double px, double py, double radius, Visitor visitor) {
        int c0 = StrictMath.max(0, (int) ((px - radius) / CELL_MM));
        int c1 = StrictMath.min(cols - 1, (int) ((px + radius) / CELL_MM));
        int r0 = StrictMath.max(0, (int) ((py - radius) / CELL_MM));
        int r1 = StrictMath.min(rows - 1, (int) ((py + radius) / CELL_MM));
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                for (int k = head[r * cols + c]; k >= 0; k = next[k]) {
                    if (k != self) {
                        visitor.visit(k, x[k] - px, y[k] - py);
                    }
                }
            }
        }
    }

    /**
     * @return the distance from (px, py) to the nearest other robot's surface, if one lies within
     *     {@code within} of it; else {@link Double#POSITIVE_INFINITY}
     */
    double surface(int self, double px, double py, double within) {
        return nearest(self, px, py, within) < 0 ? Double.POSITIVE_INFINITY : found;
    }

    /** The distance of what {@link #nearest} found last. */
    private double found;

    /** @return the other robot whose surface is nearest to (px, py) within {@code within}, or -1 */
    int nearest(int self, double px, double py, double within) {
        return scan(self, px, py, within, false);
    }

    /**
     * The robot a contact is reported against when several touch: the lowest-numbered one whose
     * surface lies within {@code within} of (px, py). Not the nearest: two robots pressed against
     * one from both sides lie at the touching distance to within rounding, and which of them is a
     * few 1e-15 mm nearer would decide the reported side by chance.
     *
     * @return that robot, or -1
     */
    int firstTouching(int self, double px, double py, double within) {
        return scan(self, px, py, within, true);
    }

    private int scan(int self, double px, double py, double within, boolean lowestIndex) {
        if (count < 2) {
            return -1;
        }
        double best = Double.POSITIVE_INFINITY;
        int which = -1;
        double reach = within + R;
        // A centre farther than this (a margin past `reach` for rounding) is surely beyond `within`:
        // no square root is taken for it.
        double far = reach + 1e-6 + reach * 1e-12;
        double far2 = far * far;
        int c0 = StrictMath.max(0, (int) ((px - reach) / CELL_MM));
        int c1 = StrictMath.min(cols - 1, (int) ((px + reach) / CELL_MM));
        int r0 = StrictMath.max(0, (int) ((py - reach) / CELL_MM));
        int r1 = StrictMath.min(rows - 1, (int) ((py + reach) / CELL_MM));
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                for (int k = head[r * cols + c]; k >= 0; k = next[k]) {
                    if (k != self) {
                        double dx = x[k] - px;
                        double dy = y[k] - py;
                        double d2 = dx * dx + dy * dy;
                        if (d2 > far2) {
                            continue;
                        }
                        double d = StrictMath.sqrt(d2) - R;
                        // Ties go to the lower index, whatever the buckets' order.
                        if (d <= within && (lowestIndex ? which < 0 || k < which : d < best || d == best && k < which)) {
                            best = d;
                            which = k;
                        }
                    }
                }
            }
        }
        found = best;
        return which;
    }

    /**
     * How far a disc may move before it comes within {@code touch} of another robot's centre: the
     * largest fraction t in [0, 1] of the move (dx, dy) from (px, py). A disc already that close may
     * move away, not nearer.
     *
     * @param exclude the robot to leave out (the mover itself, or the robot pushing a cap), or -1
     */
    double freeFraction(int exclude, double px, double py, double touch, double dx, double dy) {
        if (count == 0 || count == 1 && exclude == 0) {
            return 1;
        }
        double a = dx * dx + dy * dy;
        if (a == 0) {
            return 1;
        }
        double reach = touch + StrictMath.sqrt(a);
        double t = 1;
        int c0 = StrictMath.max(0, (int) ((px - reach) / CELL_MM));
        int c1 = StrictMath.min(cols - 1, (int) ((px + reach) / CELL_MM));
        int r0 = StrictMath.max(0, (int) ((py - reach) / CELL_MM));
        int r1 = StrictMath.min(rows - 1, (int) ((py + reach) / CELL_MM));
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                for (int k = head[r * cols + c]; k >= 0; k = next[k]) {
                    if (k == exclude) {
                        continue;
                    }
                    double jx = x[k] - px;
                    double jy = y[k] - py;
                    double d2 = jx * jx + jy * jy;
                    if (d2 >= reach * reach) {
                        continue;
                    }
                    double toward = jx * dx + jy * dy;
                    if (d2 <= touch * touch) {
                        if (toward > 0) {
                            return 0;
                        }
                        continue;
                    }
                    // |j - s·d|² = touch²: the smaller root is where the discs first touch.
                    double disc = toward * toward - a * (d2 - touch * touch);
                    if (disc < 0) {
                        continue;
                    }
                    double sMin = (toward - StrictMath.sqrt(disc)) / a;
                    if (sMin >= 0 && sMin < t) {
                        t = sMin;
                    }
                }
            }
        }
        return t;
    }
}
