package org.kheperasim.sim.engine.model;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.SortedMap;
import java.util.TreeMap;
import org.kheperasim.sim.engine.robot.Response;
import org.kheperasim.sim.engine.robot.RobotTypes;

/**
 * The simulation's settings: link speed, the time model, and every sensor's and motor's gain,
 * calibration and noise (the paper's "sensor degradation" and "motor degradation"). Immutable; a
 * setting is changed by {@link #with(String, String)}, which checks the key and the value.
 *
 * <p>Keys are dotted names such as {@code prox.3.gain} or {@code motor.left.calibration}; run
 * {@code khepera-sim settings} to list them all with their defaults and meanings.
 */
public final class Settings {
    /** How many sensors the per-sensor settings ({@code prox.3.gain}) name: 0..7. */
    public static final int PER_SENSOR = 8;

    private enum Kind { NUMBER, FLAG, PROFILE, STEPPING, CHOICE }

    private record Def(String defaultValue, Kind kind, double min, double max, String meaning) {
    }

    private static final Map<String, Def> DEFS = new LinkedHashMap<>();
    /** The values a {@link Kind#CHOICE} setting may take, in order; the first is the default. */
    private static final Map<String, java.util.List<String>> CHOICES = new LinkedHashMap<>();

    static {
        DEFS.put("engine.stepping", new Def("events", Kind.STEPPING, 0, 0, "how the engine advances time: events"
                + " (from event to event along exact arcs, the default) or tick (every millisecond, the reference)"));
        num("link.baud", "38400", 300, 1_000_000,
                "serial line speed, bits/s: sets how often sensor values refresh and how late commands take effect");
        num("link.turnaroundUs", "500", 0, 100_000,
                "robot's time from the end of a command to the start of its reply, microseconds");
        num("api.callCostUs", "20", 0.001, 1_000_000,
                "simulated cost of each API call a controller makes, microseconds");
        num("noise.reading", "1", 0, 100, "scale of every per-reading noise (0 switches it off)");
        num("noise.robot", "1", 0, 100, "scale of every per-robot miscalibration drawn once a run (0 switches it off)");
        DEFS.put("prox.profile",
                new Def("khepera1", Kind.PROFILE, 0, 0,
                        "proximity response table: khepera1 (default), khepera2, or sample:PATH (a table fitted to a"
                                + " sampled .sample wall file, docs/calibration.md)"));
        num("prox.offset", "15", 0, 1023, "proximity reading with nothing in range (the noise floor), counts");
        num("prox.offsetSpread", "10", 0, 1023, "per-robot spread of each sensor's offset, +/- counts");
        num("prox.gainSpread", "0.05", 0, 1, "per-robot spread of each sensor's gain, standard deviation (relative)");
        num("prox.noiseAbs", "3", 0, 1023, "per-reading proximity noise, standard deviation, counts");
        num("prox.noiseRel", "0.03", 0, 1, "per-reading proximity noise, standard deviation relative to the signal");
        num("prox.spikeRate", "0.0002", 0, 1, "probability that a proximity reading is a spurious spike");
        num("prox.reflect.wall", "1", 0, 10, "reflectance of walls relative to the white reference wall");
        num("prox.reflect.light", "1", 0, 10, "reflectance of light sources");
        num("prox.reflect.cap", "1", 0, 10, "reflectance of bottle caps");
        num("prox.reflect.robot", "0.8", 0, 10,
                "reflectance of another robot's body (its dark plastic reflects less than"
                + " the white reference wall)");
        num("light.dark", "480", 0, 1023, "ambient-light reading in darkness, counts (lower = brighter)");
        num("light.bright", "20", 0, 1023, "ambient-light reading right next to a lamp, counts");
        num("light.darkSpread", "10", 0, 1023,
                "per-robot spread of each sensor's darkness value, standard deviation, counts");
        num("light.flickerRate", "0.02", 0, 1, "probability that a reading in darkness deviates (the paper: 2%)");
        num("light.flickerDepth", "0.005", 0, 1, "largest relative deviation of such a reading (the paper: 0.005)");
        num("light.noiseRel", "0.01", 0, 1, "per-reading noise of the light signal, standard deviation (relative)");
        for (int i = 0; i < PER_SENSOR; i++) {
            num("prox." + i + ".gain", "1", 0, 10, "gain of proximity sensor " + i);
            num("prox." + i + ".noise", "1", 0, 100, "noise multiplier of proximity sensor " + i);
            flag("prox." + i + ".dead", "dead proximity sensor " + i + " (reads 0)");
            num("light." + i + ".gain", "1", 0, 10, "gain of light sensor " + i);
            flag("light." + i + ".dead", "dead light sensor " + i + " (reads as darkness)");
        }
        for (String w : new String[] {"left", "right"}) {
            num("motor." + w + ".calibration", "1", 0, 10,
                    "actual over commanded speed of the " + w + " wheel (worn motor < 1)");
            num("motor." + w + ".noise", "0.009", 0, 10,
                    "speed noise of the " + w + " wheel, standard deviation (relative), redrawn every 50 ms");
        }
        num("motor.spread", "0.02", 0, 1,
                "per-robot spread of each wheel's calibration, standard deviation (relative)");
        num("gripper.armTravelMs", "1000", 1, 60_000,
                "time the gripper arm takes between up and down, ms (an estimate: the turret's manual was not found)");
        num("gripper.fingerMs", "400", 1, 10_000, "time the gripper fingers take to open or close, ms (an estimate)");
        num("gripper.capResistivity", "120", 0, 255,
                "resistivity reading of a held bottle cap, 0..255 (empty fingers read 0)");
        num("encoder.mmPerPulse", "0.08", 0.001, 10,
                "wheel travel per encoder pulse, mm (the manual also gives 1/12 mm)");
        choice("gripper.armInView", "what the lowered gripper arm does to the proximity sensors: none (the default: it"
                + " stays out of their beams), front (sensors 2 and 3 read as touching it) or wsu (sensors"
                + " 0 to 5 read as touching it, as in the WSU simulator)", "none", "front", "wsu");
        num("vision.refreshMs", "50", 1, 10_000, "time between two images of the K213 vision turret, ms (an estimate:"
                + " its manual says its light detector adapts the scan speed to the light)");
        num("vision.noise", "0.5", 0, 255, "per-pixel noise of the vision turret, standard deviation, grey levels");
        num("vision.grey.wall", "10", 0, 255,
                "grey level the vision turret sees on a wall in the room's light (0 black, 255 white)");
        num("vision.grey.cap", "200", 0, 255, "grey level of a cap or ball in the room's light");
        num("vision.grey.robot", "60", 0, 255, "grey level of another robot's body in the room's light");
        num("vision.grey.background", "0", 0, 255, "grey level of a pixel that sees nothing (beyond the arena)");
        num("vision.lampGain", "0.25", 0, 10, "how much brighter a surface looks lit by a lamp at full exposure (the"
                + " light sensors' exposure model); a lamp itself is always 255");
        num("vision.fieldOfViewDeg", "36", 1, 180, "the vision turret's field of view, degrees (its manual: about 36)");
        num("vision.lensMm", "20", -100, 100,
                "where the vision turret's lens is, mm ahead of the robot's centre (an estimate"
                + " from the turret's layout)");
        choice("controller.mode", "where the controller runs: auto (the default: a step controller on the robot, any"
                + " other through the serial link), onboard (on the robot's own processor: it reads the latest"
                + " 20 ms scan and its commands act at once, as swarms and evolutionary robotics run it) or tethered"
                + " (on the host, through the serial link: values refresh at the poll rate the baud allows, commands"
                + " act after their wire time)",
                "auto", "onboard", "tethered");
        choice("wsu.positionUnits", "unit of a WSU controller's wheel positions: pulses (the Khepera's 0.08 mm encoder"
                + " pulses, the default) or legacy (the original simulator's counts, 3 per degree of a"
                + " turn on the spot)",
                "pulses", "legacy");
        choice("wsu.speedUnits",
                "unit of a WSU controller's wheel speeds: khepera (one Khepera speed unit, about 8 mm/s,"
                + " the default) or legacy (as fast as the original simulator drew it, about 30 mm/s: 3.78"
                + " Khepera units)",
                "khepera", "legacy");
        choice(LoopTiming.KEY, "how long a WSU controller's pause between two doWork() calls lasts: exact (the default:"
                + " what it asks, 20 ms) or desktop (as the original simulator's loop ran on a desktop Java: 20.1 ms"
                + " at the median, now and then much longer; docs/wsu-migration.md)",
                LoopTiming.EXACT, LoopTiming.DESKTOP);
        choice(WsuProfile.KEY, "behaviour profile: robot (the default: the real Khepera) or wsu (the original WSU"
                + " simulator: the robot file wsu and the settings docs/wsu-migration.md lists; a setting given"
                + " explicitly wins)", "robot", WsuProfile.WSU);
    }

    private static void choice(String key, String meaning, String... values) {
        DEFS.put(key, new Def(values[0], Kind.CHOICE, 0, 0, meaning));
        CHOICES.put(key, java.util.List.of(values));
    }

    private static void num(String key, String def, double min, double max, String meaning) {
        DEFS.put(key, new Def(def, Kind.NUMBER, min, max, meaning));
    }

    private static void flag(String key, String meaning) {
        DEFS.put(key, new Def("false", Kind.FLAG, 0, 1, meaning));
    }

    private static final Settings DEFAULTS = new Settings(new TreeMap<>());

    private final TreeMap<String, String> overrides;

    private Settings(TreeMap<String, String> overrides) {
        this.overrides = overrides;
    }

    /** @return the default settings */
    public static Settings defaults() {
        return DEFAULTS;
    }

    /**
     * @param key a setting's name
     * @return true for a setting that holds for the whole run, not for one robot of it: how the
     *     engine advances time
     */
    public static boolean wholeRun(String key) {
        return key.equals("engine.stepping");
    }

    /**
     * @param key a setting's name
     * @param value its new value
     * @return settings with that one changed
     * @throws IllegalArgumentException naming the key, the value and what is allowed
     */
    public Settings with(String key, String value) {
        Def def = DEFS.get(key);
        if (def == null) {
            throw new IllegalArgumentException("unknown setting '" + key + "'; list them with 'khepera-sim settings'");
        }
        String v = value.trim();
        switch (def.kind) {
            case NUMBER -> {
                // Plain decimals only: Double.parseDouble would also take 0x1p10, 1d, NaN and Infinity.
                if (!v.matches("[+-]?+(\\d++(\\.\\d*+)?+|\\.\\d++)([eE][+-]?+\\d++)?+")) {
                    throw new IllegalArgumentException("setting " + key + "=" + value + ": not a decimal number;"
                            + " write it like 12, -0.5 or 1.5e3");
                }
                double d = Double.parseDouble(v);
                if (!(d >= def.min && d <= def.max)) {
                    throw new IllegalArgumentException("setting " + key + "=" + value + ": must lie in "
                            + fmt(def.min) + ".." + fmt(def.max) + " (" + def.meaning + ")");
                }
            }
            case FLAG -> {
                if (!v.equals("true") && !v.equals("false")) {
                    throw new IllegalArgumentException("setting " + key + "=" + value + ": must be true or false");
                }
            }
            case PROFILE -> RobotTypes.profile(v);
            case CHOICE -> {
                if (!CHOICES.get(key).contains(v)) {
                    throw new IllegalArgumentException("setting " + key + "=" + value + ": must be one of "
                            + String.join(", ", CHOICES.get(key)) + " (" + def.meaning + ")");
                }
            }
            case STEPPING -> RobotModel.Stepping.named(v);
        }
        TreeMap<String, String> next = new TreeMap<>(overrides);
        if (v.equals(def.defaultValue) && WsuProfile.setting(overrides.get(WsuProfile.KEY), key) == null) {
            next.remove(key);
        } else {
            next.put(key, v);
        }
        return new Settings(next);
    }

    /**
     * @param assignment {@code key=value}
     * @return settings with that one changed
     */
    public Settings with(String assignment) {
        int eq = assignment.indexOf('=');
        if (eq <= 0) {
            throw new IllegalArgumentException("setting '" + assignment
                    + "' must look like key=value, e.g. prox.3.gain=0.5");
        }
        return with(assignment.substring(0, eq).trim(), assignment.substring(eq + 1));
    }

    /**
     * @param scale new scale for both noise channels @return settings with {@code noise.reading} and
     *     {@code noise.robot} set
     */
    public Settings withNoise(double scale) {
        return with("noise.reading", fmt(scale)).with("noise.robot", fmt(scale));
    }

    /** @return the numeric value of a setting */
    public double number(String key) {
        return Double.parseDouble(raw(key));
    }

    /** @return the value of a true/false setting */
    public boolean flag(String key) {
        return Boolean.parseBoolean(raw(key));
    }

    /** @return the value of a setting as text */
    public String raw(String key) {
        Def def = DEFS.get(key);
        if (def == null) {
            throw new IllegalArgumentException("unknown setting '" + key + "'");
        }
        String v = overrides.get(key);
        if (v == null) {
            v = WsuProfile.setting(overrides.get(WsuProfile.KEY), key);
        }
        return v != null ? v : def.defaultValue;
    }

    /** @return the proximity response that {@code prox.profile} names */
    public Response proximityProfile() {
        return RobotTypes.profile(raw("prox.profile"));
    }

    /** @return the settings that differ from the defaults, sorted by key */
    public SortedMap<String, String> overrides() {
        return Collections.unmodifiableSortedMap(overrides);
    }

    /** @return every setting's key, default and meaning, in a stable order */
    public static Map<String, String[]> catalogue() {
        Map<String, String[]> out = new LinkedHashMap<>();
        DEFS.forEach((k, d) -> out.put(k, new String[] {d.defaultValue, d.meaning}));
        return out;
    }

    /** @return the overrides as {@code key=value} joined by spaces, or {@code defaults} */
    public String describe() {
        if (overrides.isEmpty()) {
            return "defaults";
        }
        StringBuilder sb = new StringBuilder();
        overrides.forEach((k, v) -> sb.append(sb.length() == 0 ? "" : " ").append(k).append('=').append(v));
        return sb.toString();
    }

    private static String fmt(double d) {
        return d == StrictMath.rint(d) && StrictMath.abs(d) < 1e15 ? Long.toString((long) d) : Double.toString(d);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Settings s && s.overrides.equals(overrides);
    }

    @Override
    public int hashCode() {
        return overrides.hashCode();
    }

    @Override
    public String toString() {
        return describe();
    }
}
