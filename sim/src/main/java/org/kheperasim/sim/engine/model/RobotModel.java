package org.kheperasim.sim.engine.model;

import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.sim.engine.robot.Response;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;

/**
 * The typed form of a robot's {@link Settings} over its {@link RobotType}: read once when the robot
 * is built, so the model's parts never look a setting up by its string key. Each record holds one
 * part's numbers; the meanings and defaults are in {@link Settings} ({@code khepera-sim settings}
 * lists them). A setting that the robot type also gives (the proximity response, offset and noise,
 * the light levels, the encoder) is the type's unless the settings change it.
 *
 * @param type the robot's type: its body, wheels and sensors
 * @param stepping how the engine advances time
 * @param link the serial link and the API's time cost
 * @param noise the two noise channels' scales
 * @param proximity the proximity sensors
 * @param light the ambient-light sensors
 * @param motors the wheels and encoders
 * @param gripper the gripper turret
 */
public record RobotModel(RobotType type, Stepping stepping, Link link, Noise noise, Proximity proximity,
        Light light, Motors motors,
        Gripper gripper) {

    /** How the engine advances time: the two give the same run (see {@code docs/simulation-model.md}). */
    public enum Stepping {
        /** From one event to the next, moving robots along exact arcs in between (the default). */
        EVENTS,
        /** Every millisecond: the reference the event stepping is tested against. */
        TICK;

        /** @param name {@code events} or {@code tick} @return the stepping */
        public static Stepping named(String name) {
            return switch (name) {
                case "events" -> EVENTS;
                case "tick" -> TICK;
                default -> throw new IllegalArgumentException("engine.stepping '" + name + "' must be events or tick");
            };
        }
    }

    /**
     * @param timing the link's timing model
     * @param apiCostNanos simulated cost of one API call, ns
     */
    public record Link(LinkTiming timing, long apiCostNanos) {
    }

    /**
     * @param reading scale of every per-reading noise
     * @param robot scale of every per-robot miscalibration
     */
    public record Noise(double reading, double robot) {
    }

    /**
     * Proximity sensors; per-sensor arrays are indexed like the type's sensors.
     *
     * @param profile response over distance and angle
     * @param offset reading with nothing in range, counts
     * @param offsetSpread per-robot offset spread, ± counts
     * @param gainSpread per-robot gain spread, relative σ
     * @param noiseAbs per-reading noise σ, counts
     * @param noiseRel per-reading noise σ relative to the signal
     * @param spikeRate probability of a spurious reading
     * @param reflectance by occupancy id: floor, wall, light, cap; then another robot's body
     * @param gain per-sensor gain
     * @param noiseScale per-sensor noise multiplier
     * @param dead per-sensor failure (reads 0)
     */
    public record Proximity(Response profile, double offset, double offsetSpread, double gainSpread,
            double noiseAbs, double noiseRel, double spikeRate, double[] reflectance, double[] gain,
            double[] noiseScale, boolean[] dead) {
    }

    /**
     * Ambient-light sensors.
     *
     * @param dark reading in darkness
     * @param bright reading next to a lamp
     * @param darkSpread per-robot spread of the darkness value, σ counts
     * @param flickerRate probability that a reading in darkness deviates
     * @param flickerDepth largest relative deviation of such a reading
     * @param noiseRel per-reading noise of the signal, relative σ
     * @param noiseOfReading per-reading noise relative to the reading itself, σ (the robot file's
     *     {@code noise_of_reading})
     * @param gain per-sensor gain
     * @param dead per-sensor failure (reads darkness)
     */
    public record Light(double dark, double bright, double darkSpread, double flickerRate, double flickerDepth,
            double noiseRel, double noiseOfReading, double[] gain, boolean[] dead) {
    }

    /**
     * Wheels and encoders.
     *
     * @param calibrationLeft actual over commanded speed, left
     * @param calibrationRight actual over commanded speed, right
     * @param noiseLeft speed noise σ (relative), left, redrawn every the drive's noise period
     * @param noiseRight speed noise σ (relative), right
     * @param spread per-robot calibration spread, relative σ
     * @param mmPerPulse wheel travel per encoder pulse, mm
     */
    public record Motors(double calibrationLeft, double calibrationRight, double noiseLeft, double noiseRight,
            double spread, double mmPerPulse) {
    }

    /**
     * @param armTravelNanos the arm's travel between up and down, ns
     * @param fingerNanos the fingers' time to open or close, ns
     * @param capResistivity resistivity reading of a held cap, 0..255
     */
    public record Gripper(long armTravelNanos, long fingerNanos, int capResistivity) {
    }

    /**
     * @param s the settings
     * @return their typed form, for the default robot ({@link RobotTypes#KHEPERA1})
     */
    public static RobotModel of(Settings s) {
        return of(s, RobotTypes.KHEPERA1);
    }

    /**
     * @param s the settings
     * @param type the robot's type
     * @return their typed form
     */
    public static RobotModel of(Settings s, RobotType type) {
        int n = type.sensorCount();
        double[] proxGain = new double[n];
        double[] proxNoise = new double[n];
        boolean[] proxDead = new boolean[n];
        double[] lightGain = new double[n];
        boolean[] lightDead = new boolean[n];
        // A measured robot (a calibration) brings its own gains and wheel calibrations, multiplied into the
        // settings' (1 unless set), and draws no per-robot spread: it is that robot.
        RobotType.Measured m = type.measured();
        for (int i = 0; i < n; i++) {
            // The per-sensor settings name sensors 0..7; a ninth sensor and beyond keep the neutral values.
            boolean named = i < Settings.PER_SENSOR;
            proxGain[i] = (named ? s.number("prox." + i + ".gain") : 1) * (m == null ? 1 : m.gain(i));
            // A measured sensor's own noise, over the type's, times the settings' (1 unless set).
            proxNoise[i] = (named ? s.number("prox." + i + ".noise") : 1) * (m == null ? 1 : m.tables().noiseScale(i));
            proxDead[i] = named && s.flag("prox." + i + ".dead");
            lightGain[i] = named ? s.number("light." + i + ".gain") : 1;
            lightDead[i] = named && s.flag("light." + i + ".dead");
        }
        LinkTiming timing = new LinkTiming((int) s.number("link.baud"), LinkTiming.DEFAULT_BITS_PER_CHAR,
                (long) (s.number("link.turnaroundUs") * 1000));
        RobotType.Proximity tp = type.proximity();
        RobotType.Light tl = type.light();
        Response response = s.overrides().containsKey("prox.profile") ? s.proximityProfile() : tp.response();
        return new RobotModel(type,
                Stepping.named(s.raw("engine.stepping")),
                new Link(timing, StrictMath.max(1, (long) (s.number("api.callCostUs") * 1000))),
                new Noise(s.number("noise.reading"), s.number("noise.robot")),
                new Proximity(response, or(s, "prox.offset", tp.offset()), spread(s, "prox.offsetSpread", m),
                        spread(s, "prox.gainSpread", m), or(s, "prox.noiseAbs", tp.noiseAbs()),
                        or(s, "prox.noiseRel", tp.noiseRel()),
                        s.number("prox.spikeRate"),
                        new double[] {0, s.number("prox.reflect.wall"), s.number("prox.reflect.light"),
                            reflect(s, "prox.reflect.cap", m == null ? Double.NaN : m.capReflectance()),
                            reflect(s, "prox.reflect.robot", m == null ? Double.NaN : m.robotReflectance())},
                        proxGain, proxNoise, proxDead),
                new Light(or(s, "light.dark", tl.dark()), or(s, "light.bright", tl.bright()),
                        s.number("light.darkSpread"),
                        s.number("light.flickerRate"), s.number("light.flickerDepth"),
                        or(s, "light.noiseRel", tl.noiseRel()), tl.noiseOfReading(),
                        lightGain, lightDead),
                new Motors(s.number("motor.left.calibration") * (m == null ? 1 : m.leftCalibration()),
                        s.number("motor.right.calibration") * (m == null ? 1 : m.rightCalibration()),
                        s.number("motor.left.noise"), s.number("motor.right.noise"), spread(s, "motor.spread", m),
                        or(s, "encoder.mmPerPulse", type.drive().mmPerPulse())),
                new Gripper((long) StrictMath.rint(s.number("gripper.armTravelMs") * 1e6),
                        (long) StrictMath.rint(s.number("gripper.fingerMs") * 1e6),
                        (int) s.number("gripper.capResistivity")));
    }

    /**
     * @return an object's reflectance: the measured one (relative to the wall, so times the wall's) unless
     *     the settings set it or none was measured, else the setting
     */
    private static double reflect(Settings s, String key, double measured) {
        return Double.isNaN(measured) || s.overrides().containsKey(key) ? s.number(key)
                : measured * s.number("prox.reflect.wall");
    }

    /** @return a per-robot spread: 0 for a measured robot unless the settings set it, else the setting */
    private static double spread(Settings s, String key, RobotType.Measured m) {
        return m != null && !s.overrides().containsKey(key) ? 0 : s.number(key);
    }

    /** @return the setting's value if the settings change it, else the robot type's */
    private static double or(Settings s, String key, double typeValue) {
        return s.overrides().containsKey(key) ? s.number(key) : typeValue;
    }
}
