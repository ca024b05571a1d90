package org.kheperasim.sim.engine;

import org.kheperasim.api.IrSensor;
import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.RayHit;
import org.kheperasim.sim.engine.noise.CounterNoise;

/**
 * The eight infrared proximity sensors: each casts five beams over the occupancy grid (the centre
 * ray and two pairs either side model the IR cone), weighs the nearest hit by the response profile
 * and the surface's reflectance, then applies the sensor's gain, offset, noise and spikes.
 *
 * <p>Sample {@code k}'s noise is drawn at fixed indices of each sensor's own stream, so a sample's
 * value depends only on the pose, the world and {@code k}.
 */
final class ProximitySensing {
    private static final double[] RAY_ANGLES_DEG = {0, 12, -12, 24, -24};
    private static final double[] RAY_WEIGHTS = {1.0, 0.85, 0.85, 0.5, 0.5};
    /** Draws per sample in each sensor's stream: the Gaussian, the spike test, the spike value. */
    private static final int DRAWS = 4;

    private final OccupancyGrid grid;
    private final DistanceField field;
    private final Caps caps;
    private final SensorPlacement placement;
    private final ProximityProfile profile;
    private final double range;
    private final double[] rayCos = new double[RAY_ANGLES_DEG.length];
    private final double[] raySin = new double[RAY_ANGLES_DEG.length];
    private final double[] reflectance;
    private final double maxReflectance;
    private final double[] gain;
    private final double[] offset;
    private final double[] noiseScale = new double[IrSensor.COUNT];
    private final boolean[] dead;
    private final double noiseAbs;
    private final double noiseRel;
    private final double spikeRate;
    private final CounterNoise[] noise;
    private final RayHit hit = new RayHit();

    ProximitySensing(World world, SensorPlacement placement, RobotModel model, Miscalibration calibration,
            CounterNoise[] noise) {
        this.grid = world.grid();
        this.field = world.field();
        this.caps = world.capSet();
        this.placement = placement;
        RobotModel.Proximity p = model.proximity();
        double reading = model.noise().reading();
        this.profile = p.profile();
        this.range = profile.rangeMm();
        for (int r = 0; r < RAY_ANGLES_DEG.length; r++) {
            rayCos[r] = StrictMath.cos(StrictMath.toRadians(RAY_ANGLES_DEG[r]));
            raySin[r] = StrictMath.sin(StrictMath.toRadians(RAY_ANGLES_DEG[r]));
        }
        this.reflectance = p.reflectance();
        this.maxReflectance = StrictMath.max(reflectance[1], StrictMath.max(reflectance[2], reflectance[3]));
        this.gain = calibration.proxGain;
        this.offset = calibration.proxOffset;
        for (int i = 0; i < IrSensor.COUNT; i++) {
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
        // Caps are not in the distance field: bound the beams' empty stretch by the nearest cap too.
        double capFree = caps.count() == 0 ? Double.POSITIVE_INFINITY
                : caps.nearestSurface(robotX, robotY) - SensorPlacement.REACH_MM;
        // Nothing within range of any sensor: every beam is empty (the clearance estimate is within
        // NEAR_MM above the true one, and no sensor is farther than REACH_MM from the centre).
        boolean open = capFree >= range
                && field.clearance(robotX, robotY) - DriveBody.NEAR_MM - SensorPlacement.REACH_MM >= range;
        if (!open) {
            placement.place(robotX, robotY, c, s);
        }
        for (int i = 0; i < IrSensor.COUNT; i++) {
            if (open) {
                out[i] = reading(i, 0, sample);
                continue;
            }
            double px = placement.x[i];
            double py = placement.y[i];
            double dx = placement.dx[i];
            double dy = placement.dy[i];
            double raw = 0;
            double free = field.clearance(px, py);
            if (capFree < free) {
                free = StrictMath.min(free, capsAhead(px, py, dx, dy));
            }
            if (free < range) {
                raw = beams(px, py, dx, dy, StrictMath.max(0, free - DriveBody.NEAR_MM));
            }
            out[i] = reading(i, raw, sample);
        }
    }

    /** Sensor i's reading for a beam response {@code raw}: gain, offset, noise and spikes. */
    private int reading(int i, double raw, long sample) {
        double value = raw * gain[i] + offset[i];
        if (noiseScale[i] > 0) {
            CounterNoise n = noise[i];
            long k = sample * DRAWS;
            value += n.gaussian(k) * (noiseAbs + noiseRel * raw) * noiseScale[i];
            if (spikeRate > 0 && n.uniform(k + 1) < spikeRate) {
                value = n.uniform(k + 2) * 1023;
            }
        }
        return dead[i] ? 0 : SensorPlacement.reading(value);
    }

    /**
     * The strongest beam response; nothing lies nearer than {@code skip} (the clearance less the
     * estimate's error), so the beams start there instead of walking the empty cells.
     */
    private double beams(double px, double py, double dx, double dy, double skip) {
        double raw = 0;
        for (int r = 0; r < rayCos.length; r++) {
            // A hit beyond `reach` could not beat the strongest response so far: march no farther.
            double reach = raw == 0 ? range
                    : profile.distanceBeyondWhichAtMost(raw / (RAY_WEIGHTS[r] * maxReflectance)) + 1e-9;
            if (reach <= skip) {
                continue;
            }
            double rx = dx * rayCos[r] - dy * raySin[r];
            double ry = dy * rayCos[r] + dx * raySin[r];
            double d = skip + grid.castRay(px + skip * rx, py + skip * ry, rx, ry, StrictMath.min(range, reach) - skip, hit);
            if (d != Double.POSITIVE_INFINITY) {
                double v = RAY_WEIGHTS[r] * reflectanceOf(hit.id) * profile.valueAt(d);
                if (v > raw) {
                    raw = v;
                }
            }
        }
        return raw;
    }

    /**
     * Distance from a sensor to the nearest cap on the floor that its beams could reach: caps
     * wholly behind the sensor (all the beams point forward) do not count.
     */
    private double capsAhead(double px, double py, double dx, double dy) {
        double best = Double.POSITIVE_INFINITY;
        for (int k = 0; k < caps.count(); k++) {
            if (caps.heldBy(k) >= 0) {
                continue;
            }
            double ex = caps.x(k) - px;
            double ey = caps.y(k) - py;
            double r = caps.radius(k);
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

    private double reflectanceOf(int cellId) {
        return cellId >= OccupancyGrid.FIRST_CAP ? reflectance[3] : reflectance[cellId];
    }
}
