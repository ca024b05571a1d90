package org.kheperasim.sim.engine.robot;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Proximity responses fitted to sampled wall tables, as {@code prox.profile=sample:PATH} names them
 * (a {@code .sample} file of the evorobotpy format, {@link SampleTable}): the file is read and fitted
 * ({@link SampleFit}) once per path and run. The fit's per-sensor gains are not part of a response;
 * {@link SampleFit.Result#gains()} gives them, for {@code prox.N.gain}.
 */
public final class SampleResponses {
    /** The prefix of a {@code prox.profile} value that names a sample file. */
    public static final String PREFIX = "sample:";

    private static final Map<String, SampleFit.Result> FITS = new ConcurrentHashMap<>();
    private static final Map<String, List<Response>> PER_SENSOR = new ConcurrentHashMap<>();
    private static final Map<String, List<Response>> OBJECTS = new ConcurrentHashMap<>();

    private SampleResponses() {
    }

    /**
     * @param path a {@code .sample} file of wall readings
     * @param type the robot that took them (its radius and sensor poses)
     * @return the fit
     * @throws IllegalArgumentException (one line) if the file is missing or not a sample table
     */
    public static SampleFit.Result fit(String path, RobotType type) {
        return FITS.computeIfAbsent(path + "\n" + type.name(), k -> {
            Path file = Path.of(path);
            if (!Files.isRegularFile(file)) {
                throw new IllegalArgumentException("sample table " + path + " does not exist: give the path of a"
                        + " .sample file, e.g. prox.profile=sample:../shared/real-khepera/khepera-wall.sample");
            }
            try {
                return SampleFit.fit(type, samples(SampleTable.read(file), type));
            } catch (IOException e) {
                throw new IllegalArgumentException("sample table " + path + " cannot be read (" + e.getMessage()
                        + "): check the file's permissions");
            }
        });
    }

    /**
     * A table per sensor, each fitted to that sensor's readings alone (its own shape over distance and
     * angle, its gain in it), around one offset.
     *
     * @param type the robot that took them
     * @param samples its wall readings
     * @param offset the reading with nothing in range, counts (the shared fit's)
     * @return one table a sensor, in sensor order
     */
    public static List<Response> perSensor(RobotType type, List<SampleFit.Sample> samples, double offset) {
        return perSensor(type, samples, SampleFit.Geometry.WALL, offset);
    }

    /**
     * A table per sensor refined from a shared fit: each starts from the shared table times the sensor's
     * gain and is fitted to that sensor's readings alone, so where the sensor's readings do not reach it
     * keeps the shared shape (a calibration's few headings a sensor: 24, where a shared fit has all eight
     * sensors' readings at every cell).
     *
     * @param type the robot that took them
     * @param samples its wall readings
     * @param shared the fit of all of them
     * @return one table a sensor, in sensor order
     */
    public static List<Response> perSensor(RobotType type, List<SampleFit.Sample> samples, SampleFit.Result shared) {
        List<Response> out = new ArrayList<>();
        for (int i = 0; i < type.sensorCount(); i++) {
            int sensor = i;
            double[][] start = shared.table().values();
            for (double[] row : start) {
                for (int c = 0; c < row.length; c++) {
                    row[c] *= shared.gains()[i];
                }
            }
            List<SampleFit.Sample> own = samples.stream().filter(s -> s.sensor() == sensor).toList();
            out.add(SampleFit.fit(type, own, SampleFit.Geometry.WALL, false, shared.offset(), start).table());
        }
        return out;
    }

    private static List<Response> perSensor(RobotType type, List<SampleFit.Sample> samples, SampleFit.Geometry g,
            double offset) {
        List<Response> out = new ArrayList<>();
        for (int i = 0; i < type.sensorCount(); i++) {
            int sensor = i;
            List<SampleFit.Sample> own = samples.stream().filter(s -> s.sensor() == sensor).toList();
            out.add(SampleFit.fit(type, own, g, false, offset).table());
        }
        return out;
    }

    /**
     * @param path a {@code .sample} file of one robot's wall readings
     * @param type that robot
     * @param offset the reading with nothing in range, counts
     * @return a table per sensor fitted to it ({@link #perSensor})
     */
    public static List<Response> perSensor(String path, RobotType type, double offset) {
        return PER_SENSOR.computeIfAbsent(path + "\n" + type.name() + "\n" + offset,
                k -> perSensor(type, samples(read(path), type), offset));
    }

    /**
     * @param path a {@code .sample} file of readings of a cap or another robot (a disc)
     * @param type the robot that took them
     * @param radiusMm the object's radius, mm
     * @param offset the reading with nothing in range, counts (the wall's)
     * @return the response to that object, a table a sensor, each fitted to that sensor's readings alone
     */
    public static List<Response> object(String path, RobotType type, double radiusMm, double offset) {
        return OBJECTS.computeIfAbsent(path + "\n" + type.name() + "\n" + radiusMm + "\n" + offset,
                k -> perSensor(type, samples(read(path), type), SampleFit.Geometry.disc(radiusMm), offset));
    }

    /**
     * The light sensors' response to a lamp from a sampled light table (its activations rise with the
     * light): at each distance block, the most lit reading of any sensor at any heading (the lamp on that
     * sensor's axis), at that sensor's distance from the lamp (the block's gap plus the body's radius less
     * the sensor's distance from the centre).
     *
     * @param path a {@code .sample} light table
     * @param type the robot that took it
     * @return its lamp response
     */
    public static LampResponse lamp(String path, RobotType type) {
        SampleTable t = read(path);
        if (t.sensors() != type.sensorCount()) {
            samples(t, type);
        }
        double[] d = new double[t.blocks()];
        double[] a = new double[t.blocks()];
        for (int b = 0; b < t.blocks(); b++) {
            int best = 0;
            int at = 0;
            for (int k = 0; k < t.angles(); k++) {
                for (int i = 0; i < t.sensors(); i++) {
                    if (t.counts(b, k, i) > best) {
                        best = t.counts(b, k, i);
                        at = i;
                    }
                }
            }
            RobotType.Sensor s = type.sensor(at);
            d[b] = t.gapMm(b) + type.body().radiusMm() - StrictMath.hypot(s.xMm(), s.yMm());
            a[b] = (double) best / SampleTable.FULL_SCALE;
        }
        return new LampResponse(d, a);
    }

    private static SampleTable read(String path) {
        Path file = Path.of(path);
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException("sample table " + path + " does not exist: give the path of a"
                    + " .sample file");
        }
        try {
            return SampleTable.read(file);
        } catch (IOException e) {
            throw new IllegalArgumentException("sample table " + path + " cannot be read (" + e.getMessage()
                    + "): check the file's permissions");
        }
    }

    /**
     * @param table a sampled wall table
     * @param type the robot that took it
     * @return its readings, the sensors the robot has
     */
    public static List<SampleFit.Sample> samples(SampleTable table, RobotType type) {
        if (table.sensors() != type.sensorCount()) {
            throw new IllegalArgumentException("sample table " + table.source() + " has " + table.sensors()
                    + " sensors but robot " + type.name() + " has " + type.sensorCount()
                    + ": use a table of that robot");
        }
        List<SampleFit.Sample> out = new ArrayList<>();
        for (int t = 0; t < table.blocks(); t++) {
            for (int k = 0; k < table.angles(); k++) {
                for (int i = 0; i < table.sensors(); i++) {
                    out.add(new SampleFit.Sample(i, table.gapMm(t), table.objectRightDeg(k), table.counts(t, k, i)));
                }
            }
        }
        return out;
    }
}
