package org.kheperasim.sim.engine.sensing;

import java.util.List;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.engine.model.Miscalibration;
import org.kheperasim.sim.engine.model.RobotModel;
import org.kheperasim.sim.engine.noise.CounterNoise;
import org.kheperasim.sim.engine.robot.LampResponse;
import org.kheperasim.sim.engine.space.World;

/**
 * The robot's ambient-light sensors: each adds up the lamps it faces and that reach it unshadowed
 * (falling off with distance), maps the exposure between darkness and brightness, and applies the
 * paper's flicker in darkness and a relative noise in light. Walls and lamp bodies cast shadows;
 * caps do not.
 */
public final class LightSensing {
    /** Draws per sample in each sensor's stream: the flicker test, the flicker value, the Gaussian. */
    private static final int DRAWS = 4;

    private final World world;
    private final OccupancyGrid grid;
    private final SensorPlacement placement;
    private final double[] dark;
    private final double[] gain;
    private final boolean[] dead;
    private final double bright;
    private final double flickerRate;
    private final double flickerDepth;
    private final double noiseRel;
    /** Noise relative to the reading itself, σ (the original WSU simulator's kind); 0 for real robots. */
    private final double noiseOfReading;
    private final CounterNoise[] noise;
    /** A measured robot's response to a lamp, in place of the modelled fall-off; null: the model's. */
    private final LampResponse lamp;
    /**
     * Characters the eight values of a sample in darkness take in a reply, or -1 when that depends
     * on the flicker (a dark level close to a power of ten): then darkness is read at once.
     */
    private final int darkChars;

    public LightSensing(World world, SensorPlacement placement, RobotModel model, Miscalibration calibration,
            CounterNoise[] noise) {
        this.world = world;
        this.grid = world.grid();
        this.placement = placement;
        RobotModel.Light l = model.light();
        double reading = model.noise().reading();
        this.dark = calibration.lightDark;
        this.gain = l.gain();
        this.dead = l.dead();
        this.bright = l.bright();
        this.flickerRate = l.flickerRate() * reading;
        this.flickerDepth = l.flickerDepth();
        this.noiseRel = l.noiseRel() * reading;
        this.noiseOfReading = l.noiseOfReading() * reading;
        this.noise = noise;
        this.lamp = model.type().measured() == null ? null : model.type().measured().tables().lamp();
        this.darkChars = darkChars();
    }

    /** The reply characters of a dark sample, when every sensor's flicker keeps its number of digits. */
    private int darkChars() {
        int chars = 0;
        for (int i = 0; i < placement.count; i++) {
            // Without a flicker the reading is the dark level itself. With one, the flicker factor is
            // monotone in its uniform draw, so its extremes bound the reading.
            int n = SensorPlacement.digits(SensorPlacement.reading(dark[i]));
            if (flickerRate > 0) {
                int low = SensorPlacement.reading(flicker(i, 0));
                int high = SensorPlacement.reading(flicker(i, 1 - 0x1.0p-53));
                if (n != SensorPlacement.digits(low) || n != SensorPlacement.digits(high)) {
                    return -1;
                }
            }
            chars += n;
        }
        return chars;
    }

    /** Sensor i's dark level with a flicker of uniform draw u. */
    private double flicker(int i, double u) {
        return dark[i] * (1 + flickerDepth * (u * 2 - 1));
    }

    /**
     * Take sample {@code sample} where nothing is lit, if its reply's length is known without its
     * values: an arena without lamps, a dark level far from a power of ten. The values are then
     * computed only when somebody reads them ({@link #fillDark}); they are the same as if computed
     * now, since darkness depends on nothing but the sample's draws.
     *
     * @return the reply's characters for the eight values, or -1 when the sample must be taken with
     *     {@link #sample}
     */
    public int deferDark() {
        return world.arena().lights().isEmpty() && noiseOfReading == 0 ? darkChars : -1;
    }

    /** The eight readings of a sample in darkness ({@link #deferDark}): each sensor's dark level and flicker. */
    public void fillDark(long sample, int[] out) {
        for (int i = 0; i < placement.count; i++) {
            out[i] = SensorPlacement.reading(darkValue(i, sample * DRAWS));
        }
    }

    private double darkValue(int i, long k) {
        CounterNoise n = noise[i];
        double value = dark[i];
        if (flickerRate > 0 && n.uniform(k) < flickerRate) {
            value = flicker(i, n.uniform(k + 1));
        }
        return ofReading(n, k, value);
    }

    /** The reading with the noise of its own size ({@code noise_of_reading}), when the robot has it. */
    private double ofReading(CounterNoise n, long k, double value) {
        return noiseOfReading > 0 ? value + n.gaussian(k + 3) * noiseOfReading * value : value;
    }

    /**
     * Read the sensors of a robot at a pose.
     *
     * @param x the robot's centre, mm
     * @param y the robot's centre, mm
     * @param c cosine of its heading
     * @param s sine of its heading
     * @param sample the sample's index (keys its noise)
     * @param out receives the eight readings, 0..1023, lower = brighter
     */
    void sample(double x, double y, double c, double s, long sample, int[] out) {
        List<Light> lights = world.arena().lights();
        if (!lights.isEmpty()) {
            placement.place(x, y, c, s);
        }
        for (int i = 0; i < placement.count; i++) {
            double exposure = 0;
            if (!dead[i]) {
                for (int k = 0; k < lights.size(); k++) {
                    exposure += exposure(lights.get(k), placement.x[i], placement.y[i], placement.dx[i],
                            placement.dy[i]);
                }
            }
            CounterNoise n = noise[i];
            long k = sample * DRAWS;
            double value;
            if (exposure <= 0) {
                value = darkValue(i, k);
            } else {
                double e = StrictMath.min(1, exposure * gain[i]);
                value = dark[i] - (dark[i] - bright) * e;
                if (noiseRel > 0) {
                    value += n.gaussian(k + 2) * noiseRel * (dark[i] - value);
                }
                value = ofReading(n, k, value);
            }
            out[i] = SensorPlacement.reading(value);
        }
    }

    /** How much of a light reaches a sensor at (px, py) looking along (dx, dy); 0..intensity. */
    private double exposure(Light light, double px, double py, double dx, double dy) {
        double lx = light.x() - px;
        double ly = light.y() - py;
        double r = StrictMath.sqrt(lx * lx + ly * ly);
        if (r >= light.range()) {
            return 0;
        }
        double facing = r == 0 ? 1 : (lx * dx + ly * dy) / r;
        if (facing <= 0) {
            return 0;
        }
        if (light.isDirectional()) {
            double dir = StrictMath.toRadians(light.directionDeg());
            double towards = r == 0 ? 1 : -(lx * StrictMath.cos(dir) + ly * StrictMath.sin(dir)) / r;
            if (towards < StrictMath.cos(StrictMath.toRadians(light.spreadDeg() / 2))) {
                return 0;
            }
        }
        if (!grid.lightReaches(px, py, light.x(), light.y())) {
            return 0;
        }
        if (lamp != null) {
            return light.intensity() * facing * lamp.activation(r);
        }
        double falloff = 1 - r / light.range();
        return light.intensity() * facing * falloff * falloff;
    }
}
