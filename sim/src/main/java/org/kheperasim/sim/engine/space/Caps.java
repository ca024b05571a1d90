package org.kheperasim.sim.engine.space;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.engine.view.CapView;

/**
 * The bottle caps: discs on the floor that robots push, and that grippers pick up and put down.
 *
 * <p>A cap on the floor is painted into the occupancy grid under its own id (the gripper's barrier
 * and the vision turret see it there; the proximity beams meet its disc); the distance field holds
 * only walls and lights, so moving a cap costs a few dozen cell writes and no field update.
 * Collisions with caps are tested disc by disc.
 *
 * <p>A push moves a cap by a displacement as far as it can go: it stops at walls and lights, and
 * shoves the caps it meets ahead of it along the line between their centres (a row of up to
 * {@value #CHAIN} caps). What cannot move blocks whatever pushes it, like a wall.
 */
public final class Caps {
    /** How many caps a push may shove in a row, the first one included. */
    public static final int CHAIN = 4;
    /** Bisection steps when a push stops part-way (2⁻⁸ of a tick's step: well under a micrometre). */
    private static final int BISECT = 8;
    /** The fast clearance estimate can exceed the true one by up to 2.2 cells; below this margin, refine. */
    private static final double NEAR_MM = 3 * OccupancyGrid.CELL_MM;
    /** Nearest free spot for a dropped cap: searched on rings this far apart, out to {@link #SETTLE_MAX_MM}. */
    private static final double SETTLE_STEP_MM = 0.5;
    private static final double SETTLE_MAX_MM = 150;
    private static final double TOUCH_TOLERANCE_MM = 1e-6;

    private final OccupancyGrid grid;
    private final DistanceField field;
    /** The robots: a cap cannot be pushed into one (but the one pushing it). */
    private final Bodies bodies;
    private double[] x = new double[0];
    private double[] y = new double[0];
    private double[] r = new double[0];
    private int[] heldBy = new int[0];
    private int version;

    Caps(OccupancyGrid grid, DistanceField field, Bodies bodies) {
        this.bodies = bodies;
        this.grid = grid;
        this.field = field;
    }

    /**
     * Take the caps of an arena (at the start, or after an edit). Cap i keeps its place while a
     * gripper holds it; the grid is not touched here (the world repaints it).
     */
    void load(List<Cap> caps) {
        int n = caps.size();
        int old = x.length;
        x = Arrays.copyOf(x, n);
        y = Arrays.copyOf(y, n);
        r = Arrays.copyOf(r, n);
        heldBy = Arrays.copyOf(heldBy, n);
        for (int i = 0; i < n; i++) {
            if (i >= old) {
                heldBy[i] = -1;
            }
            if (heldBy[i] < 0) {
                x[i] = caps.get(i).x();
                y[i] = caps.get(i).y();
            }
            r[i] = caps.get(i).radius();
        }
        version++;
    }

    /** Paint every cap on the floor into the grid (after the grid was repainted). */
    void paintAll() {
        for (int i = 0; i < x.length; i++) {
            if (heldBy[i] < 0) {
                grid.paintCap(i, x[i], y[i], r[i]);
            }
        }
    }

    public int count() {
        return x.length;
    }

    public double x(int i) {
        return x[i];
    }

    public double y(int i) {
        return y[i];
    }

    public double radius(int i) {
        return r[i];
    }

    public int heldBy(int i) {
        return heldBy[i];
    }

    /** @return a counter that changes whenever a cap moves, is picked up or put down */
    public int version() {
        return version;
    }

    /** @return the caps as they are now */
    List<CapView> views() {
        List<CapView> out = new ArrayList<>(x.length);
        for (int i = 0; i < x.length; i++) {
            out.add(new CapView(i, x[i], y[i], r[i], heldBy[i]));
        }
        return out;
    }

    /**
     * @param px point, mm
     * @param py point, mm
     * @return distance from the point to the nearest edge of a cap on the floor, mm (negative
     *     inside one; +infinity with none on the floor)
     */
    public double nearestSurface(double px, double py) {
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < x.length; i++) {
            if (heldBy[i] < 0) {
                double dx = x[i] - px;
                double dy = y[i] - py;
                double d = Math.sqrt(dx * dx + dy * dy) - r[i];
                if (d < best) {
                    best = d;
                }
            }
        }
        return best;
    }

    // ---------------------------------------------------------------- pushing

    /**
     * How much of a push cap {@code i} can make, without moving anything.
     *
     * @param i the cap, on the floor
     * @param dx displacement, mm
     * @param dy displacement, mm
     * @param depth how many more caps may be shoved in a row behind this one
     * @param pusher the robot pushing (the others block the cap), or -1
     * @return the fraction of the displacement it can travel, 0..1
     */
    public double reach(int i, double dx, double dy, int depth, int pusher) {
        double t = StrictMath.min(staticReach(i, dx, dy),
                bodies.freeFraction(pusher, x[i], y[i], r[i], dx, dy, null, 0));
        if (t == 0) {
            return 0;
        }
        double len = Math.sqrt(dx * dx + dy * dy);
        for (int j = 0; j < x.length; j++) {
            if (j == i || heldBy[j] >= 0) {
                continue;
            }
            double touch = r[i] + r[j];
            double jx = x[j] - x[i];
            double jy = y[j] - y[i];
            if (jx * jx + jy * jy >= (touch + len) * (touch + len)) {
                continue;
            }
            double ex = jx - t * dx;
            double ey = jy - t * dy;
            double d2 = ex * ex + ey * ey;
            if (d2 >= touch * touch) {
                continue;
            }
            if (depth > 0 && d2 > 0) {
                double d = Math.sqrt(d2);
                double need = touch - d;
                if (reach(j, ex / d * need, ey / d * need, depth - 1, pusher) >= 1) {
                    continue;
                }
            }
            // j stays where it is: i goes only as far as touching it.
            t = Math.min(t, contactFraction(jx, jy, dx, dy, touch));
        }
        return t;
    }

    /**
     * Push cap {@code i} by as much of the displacement as it can go, shoving the caps ahead.
     *
     * @return the fraction travelled, 0..1
     */
    public double push(int i, double dx, double dy, int depth, int pusher) {
        double t = reach(i, dx, dy, depth, pusher);
        if (t <= 0) {
            return 0;
        }
        double nx = x[i] + t * dx;
        double ny = y[i] + t * dy;
        if (depth > 0) {
            for (int j = 0; j < x.length; j++) {
                if (j == i || heldBy[j] >= 0) {
                    continue;
                }
                double touch = r[i] + r[j];
                double ex = x[j] - nx;
                double ey = y[j] - ny;
                double d2 = ex * ex + ey * ey;
                if (d2 < touch * touch && d2 > 0) {
                    double d = Math.sqrt(d2);
                    double need = touch - d;
                    push(j, ex / d * need, ey / d * need, depth - 1, pusher);
                }
            }
        }
        place(i, nx, ny);
        return t;
    }

    /** The largest fraction of (dx, dy) cap i can travel before it would touch a wall or a light. */
    private double staticReach(int i, double dx, double dy) {
        double ri = r[i];
        // A cap already a hair inside an obstacle's reach (grid precision) may still move away.
        double need = Math.min(ri, clearance(x[i], y[i]));
        if (clearance(x[i] + dx, y[i] + dy) >= need) {
            return 1;
        }
        double lo = 0;
        double hi = 1;
        for (int k = 0; k < BISECT; k++) {
            double mid = (lo + hi) * 0.5;
            if (clearance(x[i] + mid * dx, y[i] + mid * dy) >= need) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    private double clearance(double px, double py) {
        double c = field.clearance(px, py);
        return c < NEAR_MM + 12 ? field.preciseClearance(px, py) : c;
    }

    /**
     * The fraction t in [0, 1] at which a disc moving by t·(dx, dy) first comes within
     * {@code touch} of a point at (jx, jy) relative to its start; 0 if it already is.
     */
    static double contactFraction(double jx, double jy, double dx, double dy, double touch) {
        double a = dx * dx + dy * dy;
        if (a == 0) {
            return 1;
        }
        double b = -2 * (jx * dx + jy * dy);
        double c = jx * jx + jy * jy - touch * touch;
        if (c <= 0) {
            return 0;
        }
        double disc = b * b - 4 * a * c;
        if (disc < 0) {
            return 1;
        }
        double t = (-b - Math.sqrt(disc)) / (2 * a);
        return t < 0 ? 1 : Math.min(1, t);
    }

    private void place(int i, double nx, double ny) {
        grid.eraseCap(i, x[i], y[i], r[i]);
        x[i] = nx;
        y[i] = ny;
        grid.paintCap(i, nx, ny, r[i]);
        version++;
    }

    // ---------------------------------------------------------------- the gripper

    /** A gripper picks cap i up: it leaves the grid and follows the gripper. */
    public void hold(int i, int robot) {
        grid.eraseCap(i, x[i], y[i], r[i]);
        heldBy[i] = robot;
        version++;
    }

    /** Cap i, held, is now at (px, py) with its gripper. */
    public void carry(int i, double px, double py) {
        x[i] = px;
        y[i] = py;
    }

    /**
     * The gripper lets cap i go above (px, py): it lands there, or at the nearest spot clear of
     * walls, lights, other caps and the disc {@code (bx, by, bodyRadius)} (the robot's body).
     *
     * @return true if it found a spot within {@value #SETTLE_MAX_MM} mm (else it lands where it
     *     is, overlapping, and will be pushed out as anything moves)
     */
    public boolean drop(int i, double px, double py, double bx, double by, double bodyRadius) {
        heldBy[i] = -1;
        version++;
        for (double ring = 0; ring <= SETTLE_MAX_MM; ring += SETTLE_STEP_MM) {
            int steps = ring == 0 ? 1 : (int) Math.ceil(2 * Math.PI * ring / SETTLE_STEP_MM);
            for (int k = 0; k < steps; k++) {
                double a = 2 * Math.PI * k / steps;
                double cx = px + ring * StrictMath.cos(a);
                double cy = py + ring * StrictMath.sin(a);
                if (free(i, cx, cy, bx, by, bodyRadius)) {
                    x[i] = cx;
                    y[i] = cy;
                    grid.paintCap(i, cx, cy, r[i]);
                    return true;
                }
            }
        }
        x[i] = px;
        y[i] = py;
        grid.paintCap(i, px, py, r[i]);
        return false;
    }

    private boolean free(int i, double cx, double cy, double bx, double by, double bodyRadius) {
        // Touching counts as free, within a nanometre: the grip point is exactly a cap's radius
        // from the body, and rounding must not decide whether a cap may drop there.
        if (clearance(cx, cy) < r[i] - TOUCH_TOLERANCE_MM) {
            return false;
        }
        double rb = r[i] + bodyRadius - TOUCH_TOLERANCE_MM;
        if ((cx - bx) * (cx - bx) + (cy - by) * (cy - by) < rb * rb) {
            return false;
        }
        for (int j = 0; j < x.length; j++) {
            if (j != i && heldBy[j] < 0) {
                double touch = r[i] + r[j] - TOUCH_TOLERANCE_MM;
                if ((cx - x[j]) * (cx - x[j]) + (cy - y[j]) * (cy - y[j]) < touch * touch) {
                    return false;
                }
            }
        }
        return true;
    }
}
