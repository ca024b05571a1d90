package org.kheperasim.sim.engine.sensing;

import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.RayHit;
import org.kheperasim.sim.engine.body.DriveBody;
import org.kheperasim.sim.engine.body.GripperModel;
import org.kheperasim.sim.engine.model.Miscalibration;
import org.kheperasim.sim.engine.model.RobotModel;
import org.kheperasim.sim.engine.noise.CounterNoise;
import org.kheperasim.sim.engine.robot.BeamResponse;
import org.kheperasim.sim.engine.robot.Response;
import org.kheperasim.sim.engine.space.Caps;
import org.kheperasim.sim.engine.space.ClearanceProof;
import org.kheperasim.sim.engine.space.RobotsInReach;
import org.kheperasim.sim.engine.space.World;

/**
 * The robot's infrared proximity sensors: each casts beams over the occupancy grid (the centre ray
 * and a pair either side for each further angle of the robot's {@link Response}: the IR cone),
 * weighs the nearest hit by the response along that beam and the surface's reflectance, then
 * applies the sensor's gain, offset, noise and spikes.
 *
 * <p>Sample {@code k}'s noise is drawn at fixed indices of each sensor's own stream, so a sample's
 * value depends only on the pose, the world and {@code k}.
 */
public final class ProximitySensing {
    /** Draws per sample in each sensor's stream: the Gaussian, the spike test, the spike value. */
    private static final int DRAWS = 4;

    private final OccupancyGrid grid;
    private final DistanceField field;
    private final Caps caps;
    private final SensorPlacement placement;
    /** How many sensors the robot has. */
    private final int count;
    /** What a beam's hit reads, by sensor, beam (the axis first, then each pair), kind of object and distance. */
    private final BeamResponse response;
    private final double range;
    /** No sensor sits farther than this from the robot's centre, mm. */
    private final double reach;
    private final int maxReading;
    /**
     * Every beam of a sensor lies in the disc of this radius whose centre is this far ahead of the
     * sensor (the circle through the sensor and the outermost beams' ends), mm.
     */
    private final double coneMid;
    private final double[] rayCos;
    private final double[] raySin;
    private final double[] gain;
    private final double[] offset;
    private final double[] noiseScale;
    private final boolean[] dead;
    private final double noiseAbs;
    private final double noiseRel;
    private final double spikeRate;
    private final CounterNoise[] noise;
    private final RayHit hit = new RayHit();
    /** The other robots a sample may see: their bodies reflect the beams too. */
    private final RobotsInReach robots;
    /**
     * The last proofs that the field leaves a disc empty, for the robot's centre ({@code [count]})
     * and each sensor's cone: a disc whose centre has moved less than the proof's slack is still
     * empty, without a lookup.
     */
    private final ClearanceProof[] proven;

    /**
     * False only in the test that checks the shortcuts: every beam of every sample is then marched
     * over the grid from its sensor to its range, and every robot within reach is looked at.
     */
    private boolean shortcuts = true;

    /** The robot's gripper, whose lowered arm some settings put in front of sensors; null: never. */
    private GripperModel arm;
    /** The sensors that read as touching the lowered arm ({@code gripper.armInView}). */
    private final boolean[] armBlinds;

    /**
     * How far a cap's cells on the grid reach beyond its disc (mm): a cell is the cap's when its
     * centre lies in the disc, so its far corner may lie half a cell's diagonal outside; and the
     * cell holding the cap's centre is the cap's whatever the radius, so for a very small cap a
     * whole diagonal.
     */
    private static final double CAP_CELLS_MM = OccupancyGrid.CELL_MM * StrictMath.sqrt(2) + 1e-6;

    /**
     * What {@link #open} found for the sample being taken: the nearest cap's cells less the sensors'
     * reach.
     */
    private double capFree;

    public ProximitySensing(World world, int self, SensorPlacement placement, RobotModel model,
            Miscalibration calibration,
            CounterNoise[] noise) {
        this.grid = world.grid();
        this.field = world.field();
        this.caps = world.capSet();
        this.placement = placement;
        RobotModel.Proximity p = model.proximity();
        double reading = model.noise().reading();
        Response response = p.profile();
        this.count = placement.count;
        this.reach = placement.reachMm;
        this.maxReading = model.type().proximity().maxReading();
        this.range = response.rangeMm();
        this.robots = new RobotsInReach(world.bodies(), self, reach + range);
        this.proven = new ClearanceProof[count + 1];
        for (int k = 0; k < proven.length; k++) {
            proven[k] = new ClearanceProof();
        }
        double[] angles = response.anglesDeg();
        int rays = 2 * angles.length - 1;
        rayCos = new double[rays];
        raySin = new double[rays];
        // The axis, then +a and -a for each further angle a: for the Khepera 0, 12, -12, 24, -24.
        for (int r = 0; r < rays; r++) {
            int j = (r + 1) / 2;
            double deg = r == 0 ? 0 : r % 2 == 1 ? angles[j] : -angles[j];
            rayCos[r] = StrictMath.cos(StrictMath.toRadians(deg));
            raySin[r] = StrictMath.sin(StrictMath.toRadians(deg));
        }
        this.response = new BeamResponse(response, p.reflectance(),
                model.type().measured() == null ? null : model.type().measured().tables(), count);
        this.coneMid = range / (2 * StrictMath.cos(StrictMath.toRadians(angles[angles.length - 1])));
        this.noiseScale = new double[count];
        this.armBlinds = new boolean[count];
        this.gain = calibration.proxGain;
        this.offset = calibration.proxOffset;
        for (int i = 0; i < count; i++) {
            noiseScale[i] = p.noiseScale()[i] * reading;
        }
        this.dead = p.dead();
        this.noiseAbs = p.noiseAbs();
        this.noiseRel = p.noiseRel();
        this.spikeRate = p.spikeRate() * reading;
        this.noise = noise;
    }

    /**
     * Read the sensors of a robot at a pose.
     *
     * @param robotX the robot's centre, mm
     * @param robotY the robot's centre, mm
     * @param c cosine of its heading
     * @param s sine of its heading
     * @param sample the sample's index (keys its noise)
     * @param out receives the eight readings, 0..1023
     */
    void sample(double robotX, double robotY, double c, double s, long sample, int[] out) {
        if (open(robotX, robotY) && shortcuts) {
            sampleOpen(sample, out);
        } else {
            sampleNear(robotX, robotY, c, s, sample, out);
        }
    }

    /**
     * Look around a robot's centre before a sample: is nothing within reach of any beam (all the
     * readings are then those of {@link #sampleOpen}, and the heading is not needed)? Otherwise
     * {@link #sampleNear} takes the sample, with what this found.
     */
    boolean open(double robotX, double robotY) {
        // Caps are not in the distance field: bound the beams' empty stretch by the nearest cap too.
        capFree = caps.count() == 0 ? Double.POSITIVE_INFINITY
                : caps.nearestSurface(robotX, robotY) - CAP_CELLS_MM - reach;
        robots.gather(robotX, robotY);
        // Only walls and lamps within any beam's reach: the distance field alone can prove a beam empty.
        boolean wallsOnly = capFree >= range && robots.count() == 0;
        // Nothing within range of any sensor: every beam is empty (no sensor is farther than
        // reach from the centre, and the field's lower bound of the clearance is exceeded).
        return wallsOnly && discEmpty(count, robotX, robotY, reach + range);
    }

    /**
     * Does the distance field prove the disc of radius {@code radius} around (x, y) free of walls and
     * lamps? Proof {@code k}'s disc, if its centre has moved less than its slack since, is still
     * free (the clearance changes no faster than the point moves).
     */
    private boolean discEmpty(int k, double x, double y, double radius) {
        if (proven[k].proves(x, y, radius)) {
            return true;
        }
        double below = field.clearanceBelow(x, y);
        if (below - radius > 0) {
            proven[k].set(x, y, below);
            return true;
        }
        return false;
    }

    /**
     * For the test of the shortcuts only: from now on, take every sample the long way (see
     * {@link #shortcuts}); the readings must not change.
     */
    void withoutShortcuts() {
        shortcuts = false;
    }

    /** The arena was edited: the field's earlier proofs no longer hold. */
    public void arenaEdited() {
        for (ClearanceProof p : proven) {
            p.forget();
        }
    }

    /** The readings of a sample where {@link #open} found nothing in reach: no beam response, only noise. */
    void sampleOpen(long sample, int[] out) {
        for (int i = 0; i < count; i++) {
            out[i] = reading(i, 0, sample);
        }
    }

    /** A sample where {@link #open} (just called at this centre) found something within reach. */
    void sampleNear(double robotX, double robotY, double c, double s, long sample, int[] out) {
        double capFree = this.capFree;
        // No cap within any beam's reach: the distance field alone can prove a beam free of walls,
        // lamps and caps (the other robots, not in the grid, are looked at on their own).
        boolean noCaps = capFree >= range && shortcuts;
        placement.place(robotX, robotY, c, s);
        for (int i = 0; i < count; i++) {
            double px = placement.x[i];
            double py = placement.y[i];
            double dx = placement.dx[i];
            double dy = placement.dy[i];
            double raw = 0;
            double midX = px + coneMid * dx;
            double midY = py + coneMid * dy;
            // Every beam of this sensor lies in this disc: proven free of walls, lamps and caps, only
            // robots can answer them.
            boolean coneFree = noCaps && discEmpty(i, midX, midY, coneMid);
            robots.inCone(midX, midY, shortcuts ? coneMid : Double.POSITIVE_INFINITY);
            if (coneFree && robots.inConeCount() == 0) {
                out[i] = reading(i, 0, sample);
                continue;
            }
            double free = field.clearance(px, py);
            if (capFree < free) {
                free = StrictMath.min(free, capsAhead(px, py, dx, dy));
            }
            if (robots.count() > 0) {
                free = StrictMath.min(free, robots.nearestSurface(px, py));
            }
            if (!shortcuts) {
                raw = beams(i, px, py, dx, dy, 0, false, false);
            } else if (free - DriveBody.NEAR_MM < range) {
                // The field's clearance is that of the nearest cell by the cells' centres: a cell up
                // to NEAR_MM nearer may still meet a beam, so the beams start there.
                raw = beams(i, px, py, dx, dy, StrictMath.max(0, free - DriveBody.NEAR_MM), noCaps, coneFree);
            }
            out[i] = reading(i, raw, sample);
        }
    }

    /**
     * Put the lowered gripper arm in front of some sensors ({@code gripper.armInView}): with the arm
     * low they read as touching it ({@code front}: sensors 2 and 3, which look straight at it;
     * {@code wsu}: sensors 0 to 5, as the WSU simulator had it; {@code none}: no sensor).
     */
    public void armInView(GripperModel gripper, String mode) {
        switch (mode) {
            case "front" -> {
                armBlinds[StrictMath.min(2, count - 1)] = true;
                armBlinds[StrictMath.min(3, count - 1)] = true;
            }
            case "wsu" -> java.util.Arrays.fill(armBlinds, 0, StrictMath.min(6, count), true);
            default -> {
                return;
            }
        }
        this.arm = gripper;
    }

    /** Sensor i's reading for a beam response {@code raw}: gain, offset, noise and spikes. */
    private int reading(int i, double raw, long sample) {
        if (arm != null && armBlinds[i] && arm.armLow()) {
            raw = StrictMath.max(raw, response.touching(i));
        }
        double value = raw * gain[i] + offset[i];
        if (noiseScale[i] > 0) {
            CounterNoise n = noise[i];
            long k = sample * DRAWS;
            value += n.gaussian(k) * (noiseAbs + noiseRel * raw) * noiseScale[i];
            if (spikeRate > 0 && n.uniform(k + 1) < spikeRate) {
                value = n.uniform(k + 2) * 1023;
            }
        }
        return dead[i] ? 0 : maxReading == 1023 ? SensorPlacement.reading(value)
                : SensorPlacement.reading(value, maxReading);
    }

    /**
     * The strongest beam response; nothing lies nearer than {@code skip} (the clearance less the
     * estimate's error), so the beams start there instead of walking the empty cells. With
     * {@code coneFree} the field has proven the sensor's cone free of walls and lamps (and there
     * are no caps within reach), so only the other robots are looked at.
     */
    private double beams(int sensor, double px, double py, double dx, double dy, double skip, boolean noCaps,
            boolean coneFree) {
        double raw = 0;
        for (int r = 0; r < rayCos.length; r++) {
            // A hit beyond `reach` could not beat the strongest response so far: march no farther.
            double reach = raw == 0 || !shortcuts ? range
                    : response.beyondAtMost(sensor, r, raw) + 1e-9;
            if (reach <= skip) {
                continue;
            }
            double rx = dx * rayCos[r] - dy * raySin[r];
            double ry = dy * rayCos[r] + dx * raySin[r];
            double limit = StrictMath.min(range, reach);
            double d;
            int kind;
            // Where the march starts: the field may prove the beam empty farther than `skip`.
            double from = coneFree || !noCaps ? skip : emptyUntil(px, py, rx, ry, skip, limit);
            if (coneFree || from > limit) {
                // The grid march would find nothing: no wall, lamp or cap along the beam.
                if (robots.inConeCount() == 0) {
                    continue;
                }
                d = Double.POSITIVE_INFINITY;
                kind = BeamResponse.FLOOR;
            } else {
                d = from + grid.castRay(px + from * rx, py + from * ry, rx, ry, limit - from, hit);
                kind = d == Double.POSITIVE_INFINITY ? BeamResponse.FLOOR : kindOf(hit.id);
            }
            if (robots.inConeCount() > 0) {
                double dr = robots.along(px, py, rx, ry);
                if (dr < d && dr <= limit) {
                    d = dr;
                    kind = BeamResponse.ROBOT;
                }
            }
            if (d != Double.POSITIVE_INFINITY) {
                double v = response.value(sensor, r, kind, d);
                if (v > raw) {
                    raw = v;
                }
            }
        }
        return raw;
    }

    /**
     * How far the distance field proves the beam from (px, py) along (rx, ry) empty, starting at
     * {@code from} (sphere tracing: every disc the field proves empty lets the beam on by its
     * radius). Near an obstacle it stops, and the grid march goes on from there: it has nothing to
     * find before, so starting it there changes nothing.
     *
     * @return the distance along the beam up to which it is empty, at least {@code from}; more than
     *     {@code to} when the whole beam is
     */
    private double emptyUntil(double px, double py, double rx, double ry, double from, double to) {
        double t = from;
        for (int k = 0; k < 8; k++) {
            double b = field.clearanceBelow(px + t * rx, py + t * ry);
            if (b <= OccupancyGrid.CELL_MM) {
                return t;
            }
            t += b;
            if (t > to) {
                return t;
            }
        }
        return t;
    }

    /**
     * Distance from a sensor to the nearest cells of a cap on the floor that its beams could reach:
     * caps wholly behind the sensor (all the beams point forward) do not count.
     */
    private double capsAhead(double px, double py, double dx, double dy) {
        double best = Double.POSITIVE_INFINITY;
        for (int k = 0; k < caps.count(); k++) {
            if (caps.heldBy(k) >= 0) {
                continue;
            }
            double ex = caps.x(k) - px;
            double ey = caps.y(k) - py;
            double r = caps.radius(k) + CAP_CELLS_MM;
            if (ex * dx + ey * dy < -r) {
                continue;
            }
            double d = StrictMath.sqrt(ex * ex + ey * ey) - r;
            if (d < best) {
                best = d;
            }
        }
        return best;
    }

    /**
     * The samples to come may see only robots {@code ids[from .. to)}, or any (null); see {@link RobotsInReach#scope}.
     */
    public void scope(int[] ids, int from, int to) {
        robots.scope(ids, from, to);
    }

    private static int kindOf(int cellId) {
        return cellId >= OccupancyGrid.FIRST_CAP ? BeamResponse.CAP : cellId;
    }
}
