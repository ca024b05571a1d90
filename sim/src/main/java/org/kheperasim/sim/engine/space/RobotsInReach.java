package org.kheperasim.sim.engine.space;

import java.util.Arrays;

/**
 * The other robots one robot's proximity sample may see: gathered around its centre before the
 * sample ({@link #gather}), then narrowed to each sensor's cone ({@link #inCone}), whose beams
 * meet their bodies ({@link #along}).
 */
public final class RobotsInReach {
    private final Bodies bodies;
    private final int self;
    /** How far from the sampling robot's centre its beams reach, mm. */
    private final double beamReach;
    /**
     * Another robot's centre farther than this from the sampling robot's is out of every beam's
     * reach, mm: the beams' reach and the widest body ({@link #gather} sets it).
     */
    private double reachable;
    /** Centres and radii of the other robots within reach of a sample's beams, and how many. */
    private double[] nearX = new double[4];
    private double[] nearY = new double[4];
    private double[] nearR = new double[4];
    private int near;
    /** Of those, the ones whose bodies reach into the present sensor's cone (indices), and how many. */
    private int[] cone = new int[4];
    private int inCone;
    private double gatherX;
    private double gatherY;
    /**
     * Notes the robots within {@link #reachable} of ({@link #gatherX}, {@link #gatherY}); made once, not per sample.
     */
    private final Bodies.Visitor gather = this::note;
    /** The only robots the samples may see, {@code scope[scopeFrom .. scopeTo)}, or null: any ({@link #scope}). */
    private int[] scope;
    private int scopeFrom;
    private int scopeTo;

    /**
     * @param bodies every robot's body
     * @param self the sampling robot
     * @param beamReach how far from its centre a beam reaches, mm
     */
    public RobotsInReach(Bodies bodies, int self, double beamReach) {
        this.bodies = bodies;
        this.self = self;
        this.beamReach = beamReach;
    }

    /**
     * The samples to come may see only robots {@code ids[from .. to)}: their mover knows no other
     * can come within reach meanwhile (the readings are the same as with every robot looked at,
     * without scanning the buckets around). {@code ids} null: any robot.
     */
    public void scope(int[] ids, int from, int to) {
        scope = ids;
        scopeFrom = from;
        scopeTo = to;
    }

    /** Note the other robots whose bodies a beam of a sample taken at (robotX, robotY) could reach. */
    public void gather(double robotX, double robotY) {
        near = 0;
        if (bodies.count() < 2) {
            return;
        }
        gatherX = robotX;
        gatherY = robotY;
        reachable = beamReach + bodies.maxRadius();
        if (scope == null) {
            bodies.visit(self, robotX, robotY, reachable, gather);
            return;
        }
        for (int j = scopeFrom; j < scopeTo; j++) {
            int k = scope[j];
            note(k, bodies.x(k) - robotX, bodies.y(k) - robotY);
        }
    }

    /** @return how many robots {@link #gather} found within reach */
    public int count() {
        return near;
    }

    private void note(int k, double dx, double dy) {
        if (dx * dx + dy * dy >= reachable * reachable) {
            return;
        }
        if (near == nearX.length) {
            nearX = Arrays.copyOf(nearX, near * 2);
            nearY = Arrays.copyOf(nearY, near * 2);
            nearR = Arrays.copyOf(nearR, near * 2);
        }
        nearX[near] = gatherX + dx;
        nearY[near] = gatherY + dy;
        nearR[near] = bodies.radius(k);
        near++;
    }

    /**
     * Note those robots whose bodies come within the disc of radius {@code radius} around (x, y),
     * with a margin for rounding: the sensor's beams lie in that disc (the sensor itself on its
     * edge), so no other robot can meet a beam within its range, or hold the sensor inside it.
     */
    public void inCone(double x, double y, double radius) {
        inCone = 0;
        for (int k = 0; k < near; k++) {
            double clear = radius + nearR[k] + 1e-6;
            double ex = nearX[k] - x;
            double ey = nearY[k] - y;
            if (ex * ex + ey * ey <= clear * clear) {
                if (inCone == cone.length) {
                    cone = Arrays.copyOf(cone, inCone * 2);
                }
                cone[inCone++] = k;
            }
        }
    }

    /** @return how many robots {@link #inCone} noted */
    public int inConeCount() {
        return inCone;
    }

    /** @return the distance from a sensor at (px, py) to the nearest of the gathered robots' surfaces, mm */
    public double nearestSurface(double px, double py) {
        double best = Double.POSITIVE_INFINITY;
        for (int k = 0; k < near; k++) {
            double ex = nearX[k] - px;
            double ey = nearY[k] - py;
            best = StrictMath.min(best, StrictMath.sqrt(ex * ex + ey * ey) - nearR[k]);
        }
        return best;
    }

    /**
     * @return how far a beam from (px, py) along the unit vector (rx, ry) goes before it meets one of
     *     the robots in the sensor's cone, mm (the others could only be met beyond its range)
     */
    public double along(double px, double py, double rx, double ry) {
        double best = Double.POSITIVE_INFINITY;
        for (int j = 0; j < inCone; j++) {
            int k = cone[j];
            double rr = nearR[k] * nearR[k];
            double wx = nearX[k] - px;
            double wy = nearY[k] - py;
            double b = wx * rx + wy * ry;
            double c = wx * wx + wy * wy - rr;
            if (c <= 0) {
                return 0;
            }
            double disc = b * b - c;
            if (b <= 0 || disc < 0) {
                continue;
            }
            best = StrictMath.min(best, b - StrictMath.sqrt(disc));
        }
        return best;
    }
}
