package org.kheperasim.sim.engine.sensing;

import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.ShapeIndex;
import org.kheperasim.sim.engine.space.Caps;
import org.kheperasim.sim.engine.space.World;

/**
 * What one sensor's beams may meet, gathered once for all its beams ({@link #gather}): the walls
 * and lamps near its cone, the floor's edge if the cone reaches it, and the caps on the floor
 * within it; then each beam is cast against those exactly ({@link #cast}). The other robots are
 * {@code RobotsInReach}'s.
 */
final class BeamTargets {
    /** Index of a cap in the reflectance table (walls and lamps have their grid ids). */
    static final int CAP = 3;
    /** Allowance for rounding when a disc is tested against the cone, mm. */
    private static final double SLACK_MM = 1e-6;

    private final World world;
    private final Caps caps;
    /** The shapes within reach of the robot's beams ({@link #near}), and how many. */
    private int[] nearShapes = new int[8];
    private int nearCount;
    private boolean nearEdge;
    private int[] seen = new int[8];
    private int mark;
    /** Of those, the ones near the present sensor's cone ({@link #gather}), and how many. */
    private int[] shapes = new int[8];
    private int shapeCount;
    private int[] capIds = new int[4];
    private int capCount;
    private boolean edge;
    /** What the last {@link #cast} met: an index of the reflectance table. */
    private int met;

    BeamTargets(World world) {
        this.world = world;
        this.caps = world.capSet();
    }

    /**
     * Before a sample: note the walls and lamps within {@code radius} of the robot's centre (x, y),
     * which holds every beam, and whether the floor's edge is.
     */
    void near(double x, double y, double radius) {
        ShapeIndex index = world.shapes();
        int n = index.count();
        if (nearShapes.length < n) {
            nearShapes = new int[n];
            shapes = new int[n];
            seen = new int[n];
            mark = 0;
        }
        if (index.clearBelow(x, y) > radius) {
            nearCount = 0;
            nearEdge = false;
            return;
        }
        if (++mark == 0) {
            java.util.Arrays.fill(seen, 0);
            mark = 1;
        }
        nearCount = index.gather(x, y, radius, nearShapes, seen, mark);
        nearEdge = index.nearEdge(x, y, radius);
    }

    /**
     * Gather what may meet a beam lying in the disc of {@code radius} around (x, y), which lies in
     * the disc {@link #near} looked in.
     *
     * @param withCaps whether caps may lie within reach (else none is looked at)
     * @param all take every shape, the edge and every cap on the floor, wherever they are: the
     *     brute-force cast the test of the shortcuts compares with
     */
    void gather(double x, double y, double radius, boolean withCaps, boolean all) {
        ShapeIndex index = world.shapes();
        if (all) {
            if (shapes.length < index.count()) {
                shapes = new int[index.count()];
            }
            shapeCount = index.count();
            for (int k = 0; k < shapeCount; k++) {
                shapes[k] = k;
            }
            edge = true;
        } else {
            shapeCount = 0;
            for (int j = 0; j < nearCount; j++) {
                int k = nearShapes[j];
                if (index.surface(k, x, y) <= radius + SLACK_MM) {
                    shapes[shapeCount++] = k;
                }
            }
            edge = nearEdge && index.nearEdge(x, y, radius);
        }
        capCount = 0;
        if (!withCaps && !all) {
            return;
        }
        for (int k = 0; k < caps.count(); k++) {
            if (caps.heldBy(k) >= 0) {
                continue;
            }
            double ex = caps.x(k) - x;
            double ey = caps.y(k) - y;
            double reach = radius + caps.radius(k) + SLACK_MM;
            if (all || ex * ex + ey * ey <= reach * reach) {
                if (capCount == capIds.length) {
                    capIds = java.util.Arrays.copyOf(capIds, capCount * 2);
                }
                capIds[capCount++] = k;
            }
        }
    }

    /** @return true when nothing was gathered: no beam can meet a wall, lamp, edge or cap */
    boolean empty() {
        return shapeCount == 0 && capCount == 0 && !edge;
    }

    /**
     * Cast a beam against what {@link #gather} found (nearest first; at equal distances a wall or
     * lamp before a cap, and the lower-numbered of each).
     *
     * @return the distance from (px, py) along the unit vector (rx, ry) to the first thing met, mm
     *     (+infinity: nothing); {@link #met} says what
     */
    double cast(double px, double py, double rx, double ry) {
        ShapeIndex index = world.shapes();
        double best = Double.POSITIVE_INFINITY;
        int bestShape = Integer.MAX_VALUE;
        met = OccupancyGrid.FLOOR;
        for (int j = 0; j < shapeCount; j++) {
            int k = shapes[j];
            double d = index.along(k, px, py, rx, ry);
            if (d < best || d == best && d != Double.POSITIVE_INFINITY && k < bestShape) {
                best = d;
                bestShape = k;
                met = index.id(k);
            }
        }
        if (edge) {
            double d = index.edgeAlong(px, py, rx, ry);
            if (d < best) {
                best = d;
                met = OccupancyGrid.WALL;
            }
        }
        for (int j = 0; j < capCount; j++) {
            int k = capIds[j];
            double d = ShapeIndex.disc(caps.x(k) - px, caps.y(k) - py, caps.radius(k), rx, ry);
            if (d < best) {
                best = d;
                met = CAP;
            }
        }
        return best;
    }

    /** @return what the last {@link #cast} met: an index of the reflectance table (FLOOR: nothing) */
    int met() {
        return met;
    }
}
