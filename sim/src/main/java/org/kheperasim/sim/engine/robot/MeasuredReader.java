package org.kheperasim.sim.engine.robot;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * Reads a robot file's {@code measured:} section (docs/robot-files.md): what is one robot's own, its
 * name and day, its sensors' gains and wheels' calibrations, and its measured tables
 * ({@link MeasuredTables}): a wall table per sensor, a table per kind of object, each sensor's noise and
 * the lamp response, each given written out or as a sampled file to fit.
 */
final class MeasuredReader {
    static final Set<String> KEYS = Set.of("robot", "date", "gains", "wheel_calibration", "cap_reflectance",
            "robot_reflectance", "noise_scale", "table_angles", "table_distances", "sensor_tables", "sensor_sample",
            "cap_table", "cap_sample", "cap_radius", "robot_table", "robot_sample", "lamp_distances",
            "lamp_activations", "lamp_sample");

    private final RobotFileReader r;
    /** The robot being read, as its kind: its body, sensors and proximity response, for the fits. */
    private final RobotType kind;

    MeasuredReader(RobotFileReader r, RobotType kind) {
        this.r = r;
        this.kind = kind;
    }

    RobotType.Measured read(RobotFileLines.Entry m) {
        int sensorCount = kind.sensorCount();
        String robot = r.text(r.need(m, "robot"));
        if (!robot.matches("[A-Za-z0-9_.-]{1,40}")) {
            throw r.error(r.need(m, "robot"),
                    "robot '" + robot + "' is not a label; use 1 to 40 letters, digits, '_' or '-'");
        }
        String date = r.text(r.need(m, "date"));
        if (!date.matches("\\d{4}-\\d{2}-\\d{2}")) {
            throw r.error(r.need(m, "date"), "date '" + date + "' is not a day; write it YYYY-MM-DD");
        }
        RobotFileLines.Entry g = r.need(m, "gains");
        List<Double> list = new ArrayList<>();
        for (double v : r.numbers(g, sensorCount, sensorCount)) {
            if (!(v > 0 && v <= 10)) {
                throw r.error(g, "gain " + RobotFileReader.fmt(v)
                        + " is out of range; give each sensor's gain in 0..10 (1: the type's response)");
            }
            list.add(v);
        }
        double[] wheels = r.numbers(r.need(m, "wheel_calibration"), 2, 2);
        for (double v : wheels) {
            if (!(v >= 0.5 && v <= 2)) {
                throw r.error(r.need(m, "wheel_calibration"), "wheel calibration " + RobotFileReader.fmt(v)
                        + " is out of range; give the left and right wheels' actual over commanded speed,"
                        + " each in 0.5..2");
            }
        }
        double cap = m.keys.containsKey("cap_reflectance")
                ? r.number(m.keys.get("cap_reflectance"), 0, 10, "(the wall: 1)") : Double.NaN;
        double other = m.keys.containsKey("robot_reflectance")
                ? r.number(m.keys.get("robot_reflectance"), 0, 10, "(the wall: 1)") : Double.NaN;
        return new RobotType.Measured(robot, date, list, wheels[0], wheels[1], cap, other, tables(m, sensorCount));
    }

    private MeasuredTables tables(RobotFileLines.Entry m, int sensorCount) {
        MeasuredTables t = MeasuredTables.NONE;
        if (m.keys.containsKey("noise_scale")) {
            List<Double> n = new ArrayList<>();
            for (double v : r.numbers(m.keys.get("noise_scale"), sensorCount, sensorCount)) {
                if (!(v >= 0 && v <= 100)) {
                    throw r.error(m.keys.get("noise_scale"), "noise scale " + RobotFileReader.fmt(v)
                            + " is out of range; give each sensor's noise over the type's, 0..100");
                }
                n.add(v);
            }
            t = t.withNoise(n);
        }
        double offset = kind.proximity().offset();
        List<Response> sensors = new ArrayList<>();
        if (m.keys.containsKey("sensor_sample")) {
            once(m, "sensor_sample", "sensor_tables");
            RobotFileLines.Entry e = m.keys.get("sensor_sample");
            sensors = fit(e, () -> SampleResponses.perSensor(r.path(e).toString(), kind, offset));
        } else if (m.keys.containsKey("sensor_tables")) {
            RobotFileLines.Entry e = m.keys.get("sensor_tables");
            sensors = rows(m, e, sensorCount);
        }
        List<Response> capTable = object(m, "cap", () -> number(m, "cap_radius", 1, 200, 9), offset, sensorCount);
        List<Response> robotTable = object(m, "robot", () -> kind.body().radiusMm(), offset, sensorCount);
        t = t.withSensors(sensors).withObjects(capTable, robotTable);
        if (m.keys.containsKey("lamp_sample")) {
            once(m, "lamp_sample", "lamp_distances");
            RobotFileLines.Entry e = m.keys.get("lamp_sample");
            t = t.withLamp(fit(e, () -> SampleResponses.lamp(r.path(e).toString(), kind)));
        } else if (m.keys.containsKey("lamp_distances")) {
            RobotFileLines.Entry d = m.keys.get("lamp_distances");
            double[] mm = r.numbers(d, 2, 200);
            double[] a = r.numbers(r.need(m, "lamp_activations"), mm.length, mm.length);
            try {
                t = t.withLamp(new LampResponse(mm, a));
            } catch (IllegalArgumentException x) {
                throw r.error(d, x.getMessage());
            }
        }
        return t;
    }

    /**
     * A cap's or another robot's tables: fitted to its sample file (a disc of that radius; a table a sensor),
     * or written out (one table for every sensor, or one a sensor).
     */
    private List<Response> object(RobotFileLines.Entry m, String what, java.util.function.DoubleSupplier radius,
            double offset, int sensorCount) {
        if (m.keys.containsKey(what + "_sample")) {
            once(m, what + "_sample", what + "_table");
            RobotFileLines.Entry e = m.keys.get(what + "_sample");
            double rad = radius.getAsDouble();
            return fit(e, () -> SampleResponses.object(r.path(e).toString(), kind, rad, offset));
        }
        if (m.keys.containsKey(what + "_table")) {
            RobotFileLines.Entry e = m.keys.get(what + "_table");
            int angles = r.numbers(r.need(m, "table_angles"), 1, 16).length;
            return rows(m, e, e.items.size() == angles ? 1 : sensorCount);
        }
        return List.of();
    }

    /** {@code count} tables from an entry's rows, each one row per angle of {@code table_angles}. */
    private List<Response> rows(RobotFileLines.Entry m, RobotFileLines.Entry e, int count) {
        double[] angles = r.numbers(r.need(m, "table_angles"), 1, 16);
        double[] distances = r.numbers(r.need(m, "table_distances"), 2, 200);
        if (!e.value.isEmpty() || e.items.size() != count * angles.length) {
            throw r.error(e, e.key + " has " + e.items.size() + " rows; give " + count * angles.length
                    + " ('    - [...]',"
                    + (count > 1 ? " each sensor's " : " ") + angles.length + " rows, one per angle of table_angles)");
        }
        List<Response> out = new ArrayList<>();
        for (int k = 0; k < count; k++) {
            double[][] v = new double[angles.length][];
            for (int j = 0; j < angles.length; j++) {
                v[j] = r.numbers(e.items.get(k * angles.length + j), distances.length, distances.length);
            }
            try {
                out.add(new Response.Table(distances, angles, v));
            } catch (IllegalArgumentException x) {
                throw r.error(e.items.get(k * angles.length), x.getMessage());
            }
        }
        return out;
    }

    private double number(RobotFileLines.Entry m, String key, double min, double max, double dflt) {
        return m.keys.containsKey(key) ? r.number(m.keys.get(key), min, max, "mm") : dflt;
    }

    private void once(RobotFileLines.Entry m, String sample, String written) {
        if (m.keys.containsKey(written)) {
            throw r.error(m.keys.get(written), "'" + written + "' and '" + sample + "' both give it; keep one");
        }
    }

    private <T> T fit(RobotFileLines.Entry e, java.util.function.Supplier<T> f) {
        try {
            return f.get();
        } catch (IllegalArgumentException x) {
            throw r.error(e, x.getMessage());
        }
    }
}
