package org.kheperasim.sim.engine.robot;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * A calibration file ({@code khepera-calibration 1}, written by {@code khepera-link calibrate};
 * docs/calibration.md) read as the robot it measured: {@code khepera1} with the wall file's
 * readings fitted into its proximity table, offset and noise ({@link SampleFit}), the wheels'
 * measured numbers in its drive, and what one robot has of its own (each sensor's gain, each
 * wheel's calibration) as its {@link RobotType.Measured}. Anywhere a robot file is taken
 * ({@code --robot-file}, an arena's robot line, the window) a calibration is taken too.
 *
 * @param robot the robot's name
 * @param date the day it was measured
 * @param type the calibrated type
 * @param fit the fitted proximity response
 */
public record Calibration(String robot, String date, RobotType type, SampleFit.Result fit) {
    /** The first line of a calibration file. */
    public static final String MAGIC = "khepera-calibration 1";

    /**
     * @param text a file's text
     * @return whether it is a calibration (its first line is {@link #MAGIC})
     */
    public static boolean is(String text) {
        int end = text.indexOf('\n');
        return (end < 0 ? text : text.substring(0, end)).trim().equals(MAGIC);
    }

    /**
     * @param source the file's name as the user knows it
     * @param file the file (its wall samples are read beside it)
     * @param text its text
     * @return the calibration
     * @throws RobotFileException naming the file, the line and the fix when it is malformed or its wall
     *     file cannot be read
     */
    public static Calibration parse(String source, Path file, String text) {
        List<String> lines = List.of(text.split("\r?\n", -1));
        if (!is(text)) {
            throw new RobotFileException(source, 1, "not '" + MAGIC + "': give the .calibration file 'khepera-link"
                    + " calibrate' wrote");
        }
        String robot = null;
        String date = null;
        String wall = null;
        RobotType base = RobotTypes.KHEPERA1;
        double mmPerPulse = Double.NaN;
        double wheelBase = Double.NaN;
        double unit = Double.NaN;
        double rightOverLeft = 1;
        String samples = null;
        Series series = new Series();
        double cap = Double.NaN;
        double other = Double.NaN;
        for (int n = 1; n < lines.size(); n++) {
            String l = lines.get(n).trim();
            if (l.isEmpty() || l.startsWith("#")) {
                continue;
            }
            String[] kv = l.split("\\s+", 2);
            String v = kv.length > 1 ? kv[1].trim() : "";
            switch (kv[0]) {
                case "robot" -> robot = v;
                case "date" -> date = v;
                case "wall" -> wall = v;
                case "base" -> base = base(source, n, v);
                case "drive.mmPerPulse" -> mmPerPulse = number(source, n, v, 0.001, 10);
                case "drive.wheelBaseMm" -> wheelBase = number(source, n, v, 1, 1000);
                case "drive.mmPerSecondPerUnit" -> unit = number(source, n, v, 0.001, 1000);
                case "motor.rightOverLeft" -> rightOverLeft = number(source, n, v, 0.5, 2);
                case "reflect.cap" -> cap = number(source, n, v, 0, 10);
                case "reflect.robot" -> other = number(source, n, v, 0, 10);
                case "samples" -> samples = v;
                case "cap.series", "robot.series", "lamp" -> series.add(source, n, kv[0], v);
                default -> throw new RobotFileException(source, n + 1, "'" + kv[0] + "': the keys are robot, date,"
                        + " base, wall, samples, drive.*, motor.rightOverLeft, reflect.cap, reflect.robot,"
                        + " cap.series, robot.series and lamp");
            }
        }
        if (robot == null || date == null || wall == null) {
            throw new RobotFileException(source, 0, "lacks robot, date or wall: a calibration names its robot, its"
                    + " date and its wall file");
        }
        if (!robot.matches("[A-Za-z0-9_.-]{1,40}") || !date.matches("\\d{4}-\\d{2}-\\d{2}")) {
            throw new RobotFileException(source, 0, "robot '" + robot + "' or date '" + date + "' is not allowed: the"
                    + " robot is 1 to 40 letters, digits, '_' or '-', the date YYYY-MM-DD");
        }
        Path dir = file.toAbsolutePath().getParent();
        Path wallFile = dir.resolve(wall);
        SampleFit.Result fit;
        List<SampleFit.Sample> readings;
        double[] noise = null;
        try {
            readings = SampleResponses.samples(SampleTable.read(wallFile), base);
            fit = SampleFit.fit(base, readings);
            if (samples != null && Files.isRegularFile(dir.resolve(samples))) {
                noise = CalibrationTables.noise(dir.resolve(samples), base.sensorCount(), fit.offset());
            }
        } catch (java.io.IOException e) {
            throw new RobotFileException(source, 0, "its wall file " + wallFile + " or samples file cannot be read ("
                    + e.getMessage() + "): keep the files 'khepera-link calibrate' wrote beside it");
        } catch (IllegalArgumentException e) {
            throw new RobotFileException(source, 0, e.getMessage());
        }
        // Each sensor measured on its own: its own table (its level in it, so its gain is 1), its own noise.
        List<Response> own = SampleResponses.perSensor(base, readings, fit);
        List<Double> gains = new ArrayList<>();
        List<Double> scales = new ArrayList<>();
        for (int i = 0; i < base.sensorCount(); i++) {
            gains.add(1.0);
            scales.add(noise == null ? 1 : noise[2 + i]);
        }
        int[] front = CalibrationTables.front(base);
        double frontGain = (fit.gains()[front[0]] + fit.gains()[front[front.length - 1]]) / 2;
        MeasuredTables tables = MeasuredTables.NONE.withSensors(own).withNoise(noise == null ? List.of() : scales)
                .withObjects(series.table("cap.series", base, fit, frontGain),
                        series.table("robot.series", base, fit, frontGain))
                .withLamp(CalibrationTables.lamp(base, series.mm("lamp"), series.means("lamp")));
        RobotType.Measured measured = new RobotType.Measured(robot, date, gains, 2 / (1 + rightOverLeft),
                2 * rightOverLeft / (1 + rightOverLeft), cap, other, tables);
        RobotType.Drive d = base.drive();
        RobotType type = base.calibrated("calibration of " + robot + " on " + date + " (" + file.getFileName() + ")",
                Double.isNaN(wheelBase) ? d.wheelBaseMm() : wheelBase,
                Double.isNaN(unit) ? d.mmPerSecondPerUnit() : unit,
                Double.isNaN(mmPerPulse) ? d.mmPerPulse() : mmPerPulse, fit.table(), fit.offset(),
                noise == null ? fit.noiseAbs() : noise[0], noise == null ? fit.noiseRel() : noise[1], measured);
        return new Calibration(robot, date, type, fit);
    }

    private static RobotType base(String source, int n, String v) {
        if (!RobotTypes.BUNDLED.contains(v)) {
            throw new RobotFileException(source, n + 1, "base " + v + ": a calibration overlays a bundled robot,"
                    + " one of "
                    + String.join(", ", RobotTypes.BUNDLED));
        }
        return RobotTypes.named(v);
    }

    /** A calibration's straight-ahead series: {@code cap.series GAP m0 ..}, {@code robot.series ..} and lamp. */
    private static final class Series {
        private final java.util.Map<String, List<double[]>> lines = new java.util.HashMap<>();

        void add(String source, int n, String kind, String v) {
            String[] f = v.trim().split("\\s+");
            double[] x = new double[f.length];
            try {
                for (int k = 0; k < f.length; k++) {
                    x[k] = Double.parseDouble(f[k]);
                }
            } catch (NumberFormatException e) {
                throw new RobotFileException(source, n + 1, "'" + kind + " " + v + "': give the distance, mm, then"
                        + " each sensor's mean reading");
            }
            lines.computeIfAbsent(kind, k -> new ArrayList<>()).add(x);
        }

        double[] mm(String kind) {
            return lines.getOrDefault(kind, List.of()).stream().mapToDouble(x -> x[0]).toArray();
        }

        double[][] means(String kind) {
            return lines.getOrDefault(kind, List.of()).stream().map(x -> java.util.Arrays.copyOfRange(x, 1, x.length))
                    .toArray(double[][]::new);
        }

        Response.Table table(String kind, RobotType type, SampleFit.Result fit, double gain) {
            double[][] m = means(kind);
            for (double[] row : m) {
                if (row.length != type.sensorCount()) {
                    throw new IllegalArgumentException("a '" + kind + "' line has " + row.length + " readings but "
                            + type.name() + " has " + type.sensorCount() + " sensors");
                }
            }
            Response.Table t = m.length == 0 ? null : CalibrationTables.object(type, fit, mm(kind), m);
            if (t == null) {
                return null;
            }
            double[][] v = t.values();
            for (double[] row : v) {
                for (int c = 0; c < row.length; c++) {
                    row[c] *= gain;
                }
            }
            return new Response.Table(t.distancesMm(), t.anglesDeg(), v);
        }
    }

    private static double number(String source, int n, String v, double min, double max) {
        try {
            double x = Double.parseDouble(v);
            if (x >= min && x <= max) {
                return x;
            }
        } catch (NumberFormatException e) {
            // below
        }
        throw new RobotFileException(source, n + 1, String.format(Locale.ROOT, "value '%s': give a number in %s..%s", v,
                fmt(min), fmt(max)));
    }

    private static String fmt(double v) {
        return String.format(Locale.ROOT, "%.6f", v).replaceFirst("\\.?0+$", "");
    }
}
