package org.kheperasim.sim.engine.robot;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * Reads a robot file ({@code docs/robot-files.md}) into a {@link RobotType}, checking every field:
 * a wrong one is refused with {@code file:line: the field, its value, the allowed values}.
 */
public final class RobotFileReader {
    /** The most sensors a robot may have. */
    public static final int MAX_SENSORS = 32;
    private static final Set<String> TOP =
            Set.of("name", "source", "dialect", "turrets", "footprint", "drive", "sensors",
            "proximity", "light", "measured");
    private static final Set<String> FOOTPRINT = Set.of("type", "radius");
    private static final Set<String> DRIVE = Set.of("wheel_base", "speed_unit", "max_speed", "encoder_resolution",
            "motor_period", "noise_period", "move_speed", "acceleration");
    private static final Set<String> SENSOR = Set.of("name", "channel", "origin");
    private static final Set<String> PROXIMITY =
            Set.of("response", "sample", "angles", "weights", "distances", "values", "offset",
            "noise_std_dev", "noise_relative", "max_reading");
    private static final Set<String> LIGHT = Set.of("dark", "bright", "noise_relative", "noise_of_reading");

    private final String source;
    private final java.nio.file.Path folder;

    private RobotFileReader(String source, java.nio.file.Path folder) {
        this.source = source;
        this.folder = folder;
    }

    /**
     * @param source the file's name as the user knows it, for errors
     * @param text the file's text
     * @return the robot type it describes
     * @throws RobotFileException naming the first wrong line, its value and the fix
     */
    public static RobotType parse(String source, String text) {
        return parse(source, text, null);
    }

    /**
     * @param source the file's name as the user knows it, for errors
     * @param text the file's text
     * @param folder where a relative {@code sample:} path is taken from (the file's folder), or null: the
     *     working folder
     * @return the robot type it describes
     * @throws RobotFileException naming the first wrong line, its value and the fix
     */
    public static RobotType parse(String source, String text, java.nio.file.Path folder) {
        return new RobotFileReader(source, folder).type(RobotFileLines.read(source, text));
    }

    private RobotType type(RobotFileLines.Entry root) {
        known(root, TOP, "the file's top level");
        String name = text(need(root, "name"));
        if (!name.matches("[A-Za-z0-9_-]{1,40}")) {
            throw error(need(root, "name"),
                    "name '" + name + "' is not allowed; use 1 to 40 letters, digits, '_' or '-'");
        }
        String src = root.keys.containsKey("source") ? text(root.keys.get("source")) : "";
        String dialect = text(need(root, "dialect"));
        if (!dialect.matches("[a-z0-9]+")) {
            throw error(need(root, "dialect"),
                    "dialect '" + dialect + "' is not a name; use e.g. khepera1, khepera2 or epuck");
        }
        Set<RobotType.Turret> turrets = EnumSet.noneOf(RobotType.Turret.class);
        if (root.keys.containsKey("turrets")) {
            RobotFileLines.Entry t = root.keys.get("turrets");
            for (String s : flow(t)) {
                try {
                    turrets.add(RobotType.Turret.valueOf(s.toUpperCase(Locale.ROOT)));
                } catch (IllegalArgumentException e) {
                    throw error(t, "turret '" + s + "' is not known; use gripper, vision, or [] for none");
                }
            }
        }
        RobotFileLines.Entry fp = section(root, "footprint", FOOTPRINT);
        if (!text(need(fp, "type")).equals("circle")) {
            throw error(need(fp, "type"), "footprint type '" + text(need(fp, "type")) + "' is not supported; use circle"
                    + " (the contact solver models round bodies)");
        }
        RobotType.Body body = new RobotType.Body(number(need(fp, "radius"), 5, 500, "mm"));
        RobotFileLines.Entry d = section(root, "drive", DRIVE);
        RobotType.Drive drive = new RobotType.Drive(number(need(d, "wheel_base"), 1, 1000, "mm"),
                number(need(d, "speed_unit"), 1e-4, 1000, "mm/s per speed unit"),
                integer(need(d, "max_speed"), 1, 100_000, "speed units"),
                number(need(d, "encoder_resolution"), 1e-4, 100, "mm per pulse"),
                millis(need(d, "motor_period")), millis(need(d, "noise_period")),
                integer(need(d, "move_speed"), 1, 100_000, "speed units"),
                integer(need(d, "acceleration"), 1, 100_000, "1/256 speed unit per motor period"));
        if (drive.moveSpeed() > drive.maxSpeed()) {
            throw error(need(d, "move_speed"), "move_speed " + drive.moveSpeed() + " is above max_speed "
                    + drive.maxSpeed() + "; lower it");
        }
        if (drive.wheelBaseMm() > 2 * body.radiusMm()) {
            throw error(need(d, "wheel_base"), "wheel_base " + fmt(drive.wheelBaseMm()) + " mm is wider than the body ("
                    + fmt(2 * body.radiusMm()) + " mm across); the wheels sit under the disc");
        }
        List<RobotType.Sensor> sensors = sensors(need(root, "sensors"), body);
        RobotFileLines.Entry l = section(root, "light", LIGHT);
        RobotType.Light light = new RobotType.Light(number(need(l, "dark"), 0, 100_000, "counts"),
                number(need(l, "bright"), 0, 100_000, "counts"),
                number(need(l, "noise_relative"), 0, 10, "(relative)"),
                l.keys.containsKey("noise_of_reading")
                        ? number(l.keys.get("noise_of_reading"), 0, 10, "(relative)") : 0);
        RobotFileLines.Entry p = section(root, "proximity", PROXIMITY);
        Response response = text(need(p, "response")).equals("sample")
                ? sampled(p, new RobotType(name, src, body, drive, sensors, RobotTypes.KHEPERA1.proximity(), light,
                        turrets, dialect))
                : response(p, name);
        RobotType.Proximity proximity =
                new RobotType.Proximity(response, number(need(p, "offset"), 0, 100_000, "counts"),
                number(need(p, "noise_std_dev"), 0, 100_000, "counts"),
                number(need(p, "noise_relative"), 0, 10, "(relative)"),
                integer(need(p, "max_reading"), 1, 100_000, "counts"));
        RobotType kind = new RobotType(name, src, body, drive, sensors, proximity, light, turrets, dialect);
        RobotType.Measured measured = root.keys.containsKey("measured")
                ? new MeasuredReader(this, kind).read(section(root, "measured", MeasuredReader.KEYS)) : null;
        try {
            return new RobotType(name, src, body, drive, sensors, proximity, light, turrets, dialect, measured);
        } catch (IllegalArgumentException e) {
            throw error(root.keys.get("measured"), e.getMessage());
        }
    }

    private List<RobotType.Sensor> sensors(RobotFileLines.Entry s, RobotType.Body body) {
        if (!s.value.isEmpty() || s.items.isEmpty()) {
            throw error(s, "sensors must be a list of '  - name: ...' items, one per sensor, 1 to " + MAX_SENSORS);
        }
        if (s.items.size() > MAX_SENSORS) {
            throw error(s.items.get(MAX_SENSORS),
                    "more than " + MAX_SENSORS + " sensors; a robot has " + MAX_SENSORS + " at most");
        }
        List<RobotType.Sensor> out = new ArrayList<>();
        Set<String> names = new HashSet<>();
        Set<Integer> channels = new HashSet<>();
        for (RobotFileLines.Entry item : s.items) {
            if (!item.value.isEmpty()) {
                throw error(item, "a sensor is a map ('- name: ...'), not a list");
            }
            known(item, SENSOR, "a sensor");
            String name = text(need(item, "name"));
            if (!name.matches("[A-Za-z0-9_]{1,20}") || !names.add(name)) {
                throw error(need(item, "name"),
                        "sensor name '" + name + "' is " + (names.contains(name) ? "used twice" : "not allowed")
                        + "; give each sensor its own name of letters, digits and '_'");
            }
            int channel = integer(need(item, "channel"), 0, s.items.size() - 1,
                    "(the index in the protocol's replies)");
            if (!channels.add(channel)) {
                throw error(need(item, "channel"),
                        "channel " + channel + " is used twice; number the sensors' channels 0 to "
                        + (s.items.size() - 1) + ", each once");
            }
            RobotFileLines.Entry o = need(item, "origin");
            double[] xyh = numbers(o, 3, 3);
            double reach = StrictMath.hypot(xyh[0], xyh[1]);
            if (reach > body.radiusMm() + 10) {
                throw error(o, "origin [" + fmt(xyh[0]) + ", " + fmt(xyh[1]) + "] is "
                        + String.format(Locale.ROOT, "%.1f", reach) + " mm from the centre,"
                        + " beyond the body (radius " + fmt(body.radiusMm()) + " mm); mount the sensor on the body");
            }
            if (xyh[2] <= -360 || xyh[2] >= 360) {
                throw error(o, "heading " + fmt(xyh[2])
                        + " is not an angle; use degrees in -360..360, 0 ahead, 90 left");
            }
            out.add(new RobotType.Sensor(name, channel, xyh[0], xyh[1], xyh[2]));
        }
        return out;
    }

    /**
     * A response fitted to a sampled wall table the file points at ({@code response: sample},
     * {@code sample: PATH}, evorobotpy's {@code .sample} format; docs/calibration.md): the table the
     * engine's beam rule turns back into the measured readings, for this robot's sensors. The fit's
     * per-sensor gains are not a kind's: a calibration gives them to one robot.
     *
     * @param shape the robot being read, with a provisional response (the fit needs its body and sensors)
     */
    private Response sampled(RobotFileLines.Entry p, RobotType shape) {
        RobotFileLines.Entry e = need(p, "sample");
        java.nio.file.Path file = path(e);
        try {
            return SampleResponses.fit(file.toString(), shape).table();
        } catch (IllegalArgumentException ex) {
            throw error(e, ex.getMessage());
        }
    }

    /** @return the path an entry gives, from the robot file's folder when it is relative */
    java.nio.file.Path path(RobotFileLines.Entry e) {
        java.nio.file.Path file = java.nio.file.Path.of(text(e));
        return !file.isAbsolute() && folder != null ? folder.resolve(file) : file;
    }

    private Response response(RobotFileLines.Entry p, String robot) {
        RobotFileLines.Entry kind = need(p, "response");
        double[] angles = numbers(need(p, "angles"), 1, 16);
        double[] distances = numbers(need(p, "distances"), 2, 200);
        RobotFileLines.Entry v = need(p, "values");
        try {
            switch (text(kind)) {
                case "curve" -> {
                    if (!v.items.isEmpty()) {
                        throw error(v, "a curve's values are one list '[...]' on this line; use 'response:"
                                + " table' for rows");
                    }
                    double[] weights = numbers(need(p, "weights"), angles.length, angles.length);
                    double[] values = numbers(v, distances.length, distances.length);
                    return new Response.Curve(new ProximityProfile(robot, distances, values), angles, weights);
                }
                case "table" -> {
                    if (p.keys.containsKey("weights")) {
                        throw error(p.keys.get("weights"),
                                "a table has no weights (each angle has its own row); remove the line");
                    }
                    if (!v.value.isEmpty() || v.items.size() != angles.length) {
                        throw error(v, "a table's values are one row '    - [...]' per angle (" + angles.length
                                + " rows), each with one value per distance");
                    }
                    double[][] rows = new double[angles.length][];
                    for (int j = 0; j < rows.length; j++) {
                        rows[j] = numbers(v.items.get(j), distances.length, distances.length);
                    }
                    return new Response.Table(distances, angles, rows);
                }
                default -> throw error(kind, "response '" + text(kind) + "' is not known; use curve or table");
            }
        } catch (RobotFileException e) {
            throw e;
        } catch (IllegalArgumentException e) {
            throw error(kind, e.getMessage());
        }
    }

    // ------------------------------------------------------------------ fields

    RobotFileLines.Entry section(RobotFileLines.Entry root, String key, Set<String> keys) {
        RobotFileLines.Entry s = need(root, key);
        if (!s.value.isEmpty() || !s.items.isEmpty()) {
            throw error(s, "'" + key + ":' starts a section; put its keys on the lines below, indented two spaces");
        }
        known(s, keys, "'" + key + "'");
        return s;
    }

    private void known(RobotFileLines.Entry e, Set<String> keys, String where) {
        for (RobotFileLines.Entry k : e.keys.values()) {
            if (!keys.contains(k.key)) {
                throw error(k, "'" + k.key + "' is not a key of " + where + "; use "
                        + String.join(", ", keys.stream().sorted().toList()));
            }
        }
    }

    RobotFileLines.Entry need(RobotFileLines.Entry e, String key) {
        RobotFileLines.Entry k = e.keys.get(key);
        if (k == null) {
            throw new RobotFileException(source, e.line, "'" + key + "' is missing" + (e.line == 0 ? "" : " here")
                    + "; add '" + key + ": ...' (docs/robot-files.md lists every field)");
        }
        return k;
    }

    String text(RobotFileLines.Entry e) {
        if (e.value.isEmpty()) {
            throw error(e, "'" + e.key + "' has no value; write '" + e.key + ": <value>'");
        }
        return e.value;
    }

    double number(RobotFileLines.Entry e, double min, double max, String unit) {
        double v = parse(e, text(e));
        if (!(v >= min && v <= max)) {
            throw error(e, e.key + " " + text(e) + " is out of range; use " + fmt(min) + " to "
                    + fmt(max) + " " + unit);
        }
        return v;
    }

    private int integer(RobotFileLines.Entry e, int min, int max, String unit) {
        double v = number(e, min, max, unit);
        if (v != StrictMath.rint(v)) {
            throw error(e, e.key + " " + text(e) + " is not a whole number; use a whole number of " + unit);
        }
        return (int) v;
    }

    private long millis(RobotFileLines.Entry e) {
        double ms = number(e, 1, 10_000, "ms");
        double ns = ms * 1e6;
        if (ns != StrictMath.rint(ns)) {
            throw error(e, e.key + " " + text(e) + " ms is not a whole number of nanoseconds; round it");
        }
        return (long) ns;
    }

    private double parse(RobotFileLines.Entry e, String s) {
        try {
            if (!s.matches("-?[0-9]+(\\.[0-9]+)?([eE]-?[0-9]+)?")) {
                throw new NumberFormatException();
            }
            return Double.parseDouble(s);
        } catch (NumberFormatException x) {
            throw error(e, e.key + " '" + s + "' is not a number; write digits, e.g. 27.5");
        }
    }

    private List<String> flow(RobotFileLines.Entry e) {
        String v = e.value;
        if (!v.startsWith("[") || !v.endsWith("]")) {
            throw error(e, (e.key.equals("-") ? "a row" : e.key) + " '" + v + "' is not a list; write [a, b, c]");
        }
        String inner = v.substring(1, v.length() - 1).strip();
        List<String> out = new ArrayList<>();
        if (!inner.isEmpty()) {
            for (String part : inner.split(",", -1)) {
                out.add(part.strip());
            }
        }
        return out;
    }

    double[] numbers(RobotFileLines.Entry e, int min, int max) {
        List<String> parts = flow(e);
        String what = e.key.equals("-") ? "the row" : e.key;
        if (parts.size() < min || parts.size() > max) {
            throw error(e, what + " has " + parts.size() + " values; give "
                    + (min == max ? "" + min : min + " to " + max));
        }
        double[] out = new double[parts.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = parse(e, parts.get(i));
        }
        return out;
    }

    RobotFileException error(RobotFileLines.Entry e, String what) {
        return new RobotFileException(source, e.line, what);
    }

    /** @param v a number @return it as a robot file writes it: the shortest decimal, no trailing zeros */
    static String fmt(double v) {
        if (v == StrictMath.rint(v) && StrictMath.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return new java.math.BigDecimal(Double.toString(v)).stripTrailingZeros().toPlainString();
    }
}
