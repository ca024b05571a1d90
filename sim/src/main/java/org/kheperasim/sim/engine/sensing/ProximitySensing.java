package org.kheperasim.sim.engine.sensing;

import org.kheperasim.sim.engine.body.GripperModel;
import org.kheperasim.sim.engine.model.Miscalibration;
import org.kheperasim.sim.engine.model.RobotModel;
import org.kheperasim.sim.engine.noise.CounterNoise;
import org.kheperasim.sim.engine.robot.BeamResponse;
import org.kheperasim.sim.engine.robot.Response;
import org.kheperasim.sim.engine.space.Caps;
import org.kheperasim.sim.engine.space.RobotsInReach;
import org.kheperasim.sim.engine.space.World;

/**
 * The robot's infrared proximity sensors: each casts beams (the centre ray and a pair either side
 * for each further angle of the robot's {@link Response}: the IR cone) against the walls, lamps,
 * caps and other robots as the arena gives their shapes (capsules and discs, exactly: no grid),
 * weighs the nearest hit by the response along that beam and the surface's reflectance, then
 * applies the sensor's gain, offset, noise and spikes.
 *
 * <p>Sample {@code k}'s noise is drawn at fixed indices of each sensor's own stream, so a sample's
 * value depends only on the pose, the world and {@code k}.
 */
public final class ProximitySensing {
    /** Draws per sample in each sensor's stream: the Gaussian, the spike test, the spike value. */
    private static final int DRAWS = 4;

    private final World world;
    private final Caps caps;
    /** What the present sensor's beams may meet. */
    private final BeamTargets targets;
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
    /** The other robots a sample may see: their bodies reflect the beams too. */
    private final RobotsInReach robots;
    /**
     * False only in the test that checks the shortcuts: every beam of every sample is then cast
     * against every wall, lamp, cap on the floor and the floor's edge, and every robot within reach
     * is looked at.
     */
    private boolean shortcuts = true;

    /** The robot's gripper, whose lowered arm some settings put in front of sensors; null: never. */
    private GripperModel arm;
    /** The sensors that read as touching the lowered arm ({@code gripper.armInView}). */
    private final boolean[] armBlinds;

    /**
     * What {@link #open} found for the sample being taken: the nearest cap's distance from the robot's
     * centre less the sensors' reach, mm.
     */
    private double capFree;

    public ProximitySensing(World world, int self, SensorPlacement placement, RobotModel model,
            Miscalibration calibration,
            CounterNoise[] noise) {
        this.world = world;
        this.caps = world.capSet();
        this.targets = new BeamTargets(world);
        this.placement = placement;
        RobotModel.Proximity p = model.proximity();
        double reading = model.noise().reading();
        Response response = p.profile();
        this.count = placement.count;
        this.reach = placement.reachMm;
        this.maxReading = model.type().proximity().maxReading();
        this.range = response.rangeMm();
        this.robots = new RobotsInReach(world.bodies(), self, reach + range);
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
        this.coneMid = range / (2 * StrictMath.cos(StrictMath.toRadians(angles[angles.length - 1])));
        this.noiseScale = new double[count];
        this.armBlinds = new boolean[count];
        this.response = BeamResponse.of(model.type(), response, p.reflectance());
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
        capFree = caps.count() == 0 ? Double.POSITIVE_INFINITY : caps.nearestSurface(robotX, robotY) - reach;
        robots.gather(robotX, robotY);
        // No sensor is farther than reach from the centre, no beam longer than range: a disc of
        // reach + range holds every beam.
        return capFree > range && robots.count() == 0 && world.shapes().clearBelow(robotX, robotY) > reach + range;
    }

    /**
     * For the test of the shortcuts only: from now on, take every sample the long way (see
     * {@link #shortcuts}); the readings must not change.
     */
    void withoutShortcuts() {
        shortcuts = false;
    }

    /** The arena was edited: nothing to forget (the world's shapes are looked up at every sample). */
    public void arenaEdited() {
        // Nothing is kept between samples.
    }

    /** The readings of a sample where {@link #open} found nothing in reach: no beam response, only noise. */
    void sampleOpen(long sample, int[] out) {
        for (int i = 0; i < count; i++) {
            out[i] = reading(i, 0, sample);
        }
    }

    /** A sample where {@link #open} (just called at this centre) found something within reach. */
    void sampleNear(double robotX, double robotY, double c, double s, long sample, int[] out) {
        // Caps may lie within some beam's reach.
        boolean withCaps = !(capFree > range);
        if (shortcuts) {
            targets.near(robotX, robotY, reach + range);
        }
        placement.place(robotX, robotY, c, s);
        for (int i = 0; i < count; i++) {
            double px = placement.x[i];
            double py = placement.y[i];
            double dx = placement.dx[i];
            double dy = placement.dy[i];
            // Every beam of this sensor lies in this disc.
            double midX = px + coneMid * dx;
            double midY = py + coneMid * dy;
            robots.inCone(midX, midY, shortcuts ? coneMid : Double.POSITIVE_INFINITY);
            targets.gather(midX, midY, coneMid, withCaps, !shortcuts);
            double raw = targets.empty() && robots.inConeCount() == 0 ? 0 : beams(i, px, py, dx, dy);
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

    /** The strongest weighted response of a sensor's beams, each cast against what {@link #targets} gathered. */
    private double beams(int sensor, double px, double py, double dx, double dy) {
        double raw = 0;
        for (int r = 0; r < rayCos.length; r++) {
            double rx = dx * rayCos[r] - dy * raySin[r];
            double ry = dy * rayCos[r] + dx * raySin[r];
            double d = targets.cast(px, py, rx, ry);
            int kind = d == Double.POSITIVE_INFINITY ? BeamResponse.FLOOR : targets.met();
            if (robots.inConeCount() > 0) {
                double dr = robots.along(px, py, rx, ry);
                if (dr < d) {
                    d = dr;
                    kind = BeamResponse.ROBOT;
                }
            }
            if (d <= range) {
                double v = response.value(sensor, r, kind, d);
                if (v > raw) {
                    raw = v;
                }
            }
        }
        return raw;
    }

    /**
     * The samples to come may see only robots {@code ids[from .. to)}, or any (null); see {@link RobotsInReach#scope}.
     */
    public void scope(int[] ids, int from, int to) {
        robots.scope(ids, from, to);
    }
}
