package org.kheperasim.sim.engine.space;

import java.util.Arrays;

/**
 * Where the robots' bodies are, so that they meet each other: a uniform grid of buckets over the
 * arena, each listing the robots whose centre lies in it, so that a robot finds its neighbours
 * without looking at every other robot (contacts do not grow with N²). Every robot is a disc of its
 * type's radius. Updated whenever a robot moves; read by the robots' contacts,
 * glides and proximity beams, and by the caps (a cap cannot be pushed into a robot).
 */
public final class Bodies {
    /** Bucket size: a little more than a body's diameter. */
    static final double CELL_MM = 64;

    private final int cols;
    private final int rows;
    private final int[] head;
    private int[] next = new int[0];
    private int[] cellOf = new int[0];
    private double[] x = new double[0];
    private double[] y = new double[0];
    private double[] radius = new double[0];
    /** The widest body's radius, mm. */
    private double maxRadius;
    private int count;
    /** While robots move on two threads: their buckets are put right afterwards ({@link #relinkDeferred}). */
    private boolean deferring;
    private boolean[] pending = new boolean[0];

    /** @param width the arena's width, mm @param height its height, mm */
    Bodies(double width, double height) {
        cols = StrictMath.max(1, (int) StrictMath.ceil(width / CELL_MM));
        rows = StrictMath.max(1, (int) StrictMath.ceil(height / CELL_MM));
        head = new int[cols * rows];
        Arrays.fill(head, -1);
    }

    /** @return how many robots there are */
    public int count() {
        return count;
    }

    public double x(int i) {
        return x[i];
    }

    public double y(int i) {
        return y[i];
    }

    /** @return robot {@code i}'s body radius, mm */
    public double radius(int i) {
        return radius[i];
    }

    /** @return the widest body's radius, mm (0 before any robot joins) */
    public double maxRadius() {
        return maxRadius;
    }

    /** Robot {@code i} (the next index), a disc of radius {@code r} mm, joins at (px, py). */
    public void add(int i, double px, double py, double r) {
        if (i != count) {
            throw new IllegalArgumentException("robots join in order: expected " + count + ", got " + i);
        }
        count++;
        if (count > x.length) {
            // Grown by half again, not by one: a swarm of 1,000 robots joined one by one copied 16 MB.
            int room = StrictMath.max(8, x.length + (x.length >> 1));
            x = Arrays.copyOf(x, room);
            y = Arrays.copyOf(y, room);
            radius = Arrays.copyOf(radius, room);
            next = Arrays.copyOf(next, room);
            cellOf = Arrays.copyOf(cellOf, room);
        }
        cellOf[i] = -1;
        radius[i] = r;
        maxRadius = StrictMath.max(maxRadius, r);
        moved(i, px, py);
    }

    /**
     * Robot {@code i} is now at (px, py). While {@link #deferring}, only its own slots change: its
     * bucket follows at {@link #relinkDeferred}, so robots moved on two threads at once touch
     * nothing shared.
     */
    public void moved(int i, double px, double py) {
        x[i] = px;
        y[i] = py;
        if (deferring) {
            pending[i] = true;
            return;
        }
        relink(i);
    }

    private void relink(int i) {
        int cell = cell(x[i], y[i]);
        if (cell == cellOf[i]) {
            return;
        }
        if (cellOf[i] >= 0) {
            unlink(i);
        }
        // Each bucket lists its robots by number, whatever order they came in: what a visit finds,
        // and in which order, depends only on where the robots are.
        int prev = -1;
        int k = head[cell];
        while (k >= 0 && k < i) {
            prev = k;
            k = next[k];
        }
        next[i] = k;
        if (prev < 0) {
            head[cell] = i;
        } else {
            next[prev] = i;
        }
        cellOf[i] = cell;
    }

    /**
     * From now until {@link #relinkDeferred}, {@link #moved} keeps the buckets as they are: the
     * robots that move meanwhile must not look for others through them (robots on their own).
     */
    public void deferRelinks() {
        if (pending.length < count) {
            pending = new boolean[x.length];
        }
        deferring = true;
    }

    /** Put every robot moved since {@link #deferRelinks} into its bucket, and move on as usual. */
    public void relinkDeferred() {
        deferring = false;
        for (int i = 0; i < count; i++) {
            if (pending[i]) {
                pending[i] = false;
                relink(i);
            }
        }
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
    public interface Visitor {
        /** @param k the robot @param dx its centre's x less the point's @param dy likewise y */
        void visit(int k, double dx, double dy);
    }

    /**
     * Call {@code visitor} for every robot but {@code self} whose centre may lie within
     * {@code radius} of (px, py) (the buckets touching that disc), in a fixed order.
     */
    public void visit(int self, double px, double py, double radius, Visitor visitor) {
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
     * The robot a contact is reported against when several touch: the lowest-numbered one whose
     * surface lies within {@code within} of (px, py). Not the nearest: two robots pressed against
     * one from both sides lie at the touching distance to within rounding, and which of them is a
     * few 1e-15 mm nearer would decide the reported side by chance.
     *
     * @param among the robots that may be touching (see {@link #freeFraction}), or null: any
     * @param amongCount how many of {@code among} count
     * @return that robot, or -1
     */
    public int firstTouching(int self, double px, double py, double within, int[] among, int amongCount) {
        if (count < 2) {
            return -1;
        }
        double reach = within + maxRadius;
        // A centre farther than this (a margin past `reach` for rounding) is surely beyond `within`:
        // no square root is taken for it.
        double far = reach + 1e-6 + reach * 1e-12;
        int which = -1;
        if (among != null) {
            for (int j = 0; j < amongCount; j++) {
                which = touching(among[j], self, px, py, within, far, which);
            }
            return which;
        }
        int c0 = StrictMath.max(0, (int) ((px - reach) / CELL_MM));
        int c1 = StrictMath.min(cols - 1, (int) ((px + reach) / CELL_MM));
        int r0 = StrictMath.max(0, (int) ((py - reach) / CELL_MM));
        int r1 = StrictMath.min(rows - 1, (int) ((py + reach) / CELL_MM));
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                for (int k = head[r * cols + c]; k >= 0; k = next[k]) {
                    which = touching(k, self, px, py, within, far, which);
                }
            }
        }
        return which;
    }

    /**
     * @return {@code k} if it touches (px, py) within {@code within} and is lower than {@code which} (or that is -1),
     *     else {@code which}
     */
    private int touching(int k, int self, double px, double py, double within, double far, int which) {
        if (k == self || which >= 0 && k > which) {
            return which;
        }
        double dx = x[k] - px;
        double dy = y[k] - py;
        double d2 = dx * dx + dy * dy;
        if (d2 > far * far) {
            return which;
        }
        return StrictMath.sqrt(d2) - radius[k] <= within ? k : which;
    }

    /**
     * How far a disc of radius {@code own} may move before it touches another robot's body: the
     * largest fraction t in [0, 1] of the move (dx, dy) from (px, py). A disc already that close may
     * move away, not nearer.
     *
     * @param exclude the robot to leave out (the mover itself, or the robot pushing a cap), or -1
     * @param among the only robots it could meet during this move, or null: any (found through the
     *     buckets). A mover that knows that none or only a few others can come that near (its unit
     *     in a crowd) names them, which gives the same answer without scanning the buckets
     * @param amongCount how many of {@code among} count
     */
    public double freeFraction(int exclude, double px, double py, double own, double dx, double dy, int[] among,
            int amongCount) {
        if (count == 0 || count == 1 && exclude == 0) {
            return 1;
        }
        double a = dx * dx + dy * dy;
        if (a == 0) {
            return 1;
        }
        double step = StrictMath.sqrt(a);
        double reach = own + maxRadius + step;
        double t = 1;
        if (among != null) {
            for (int j = 0; j < amongCount && t > 0; j++) {
                t = approach(among[j], exclude, px, py, own, dx, dy, a, step, t);
            }
            return t;
        }
        int c0 = StrictMath.max(0, (int) ((px - reach) / CELL_MM));
        int c1 = StrictMath.min(cols - 1, (int) ((px + reach) / CELL_MM));
        int r0 = StrictMath.max(0, (int) ((py - reach) / CELL_MM));
        int r1 = StrictMath.min(rows - 1, (int) ((py + reach) / CELL_MM));
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                for (int k = head[r * cols + c]; k >= 0 && t > 0; k = next[k]) {
                    t = approach(k, exclude, px, py, own, dx, dy, a, step, t);
                }
            }
        }
        return t;
    }

    /**
     * @return the first of {@code among} (its first {@code amongCount}) that a disc of radius {@code own} at
     *     (px, py) already touches and the move (dx, dy) heads into, so that {@link #freeFraction} is 0 whatever
     *     the others; or -1
     */
    public int pressing(int exclude, double px, double py, double own, double dx, double dy, int[] among,
            int amongCount) {
        for (int j = 0; j < amongCount; j++) {
            int k = among[j];
            if (k != exclude && pressedBy(k, px, py, own, dx, dy)) {
                return k;
            }
        }
        return -1;
    }

    /** @return true when the move (dx, dy) of a disc of radius {@code own} at (px, py) heads into robot {@code k} */
    public boolean pressedBy(int k, double px, double py, double own, double dx, double dy) {
        // As approach() decides it, to the rounding.
        double a = dx * dx + dy * dy;
        double touch = own + radius[k];
        double reach = touch + StrictMath.sqrt(a);
        double jx = x[k] - px;
        double jy = y[k] - py;
        double d2 = jx * jx + jy * jy;
        return a != 0 && d2 < reach * reach && d2 <= touch * touch && jx * dx + jy * dy > 0;
    }

    /**
     * @return the free fraction {@code t} so far, cut short where the move meets robot {@code k} (0: it may not move
     *     nearer it at all)
     */
    private double approach(int k, int exclude, double px, double py, double own, double dx, double dy,
            double a, double step,
            double t) {
        if (k == exclude) {
            return t;
        }
        double touch = own + radius[k];
        double reach = touch + step;
        double jx = x[k] - px;
        double jy = y[k] - py;
        double d2 = jx * jx + jy * jy;
        if (d2 >= reach * reach) {
            return t;
        }
        double toward = jx * dx + jy * dy;
        if (d2 <= touch * touch) {
            return toward > 0 ? 0 : t;
        }
        // |j - s·d|² = touch²: the smaller root is where the discs first touch.
        double disc = toward * toward - a * (d2 - touch * touch);
        if (disc < 0) {
            return t;
        }
        double sMin = (toward - StrictMath.sqrt(disc)) / a;
        return sMin >= 0 && sMin < t ? sMin : t;
    }
}
