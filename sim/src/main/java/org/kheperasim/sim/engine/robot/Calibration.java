package org.kheperasim.sim.engine.robot;

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
        RobotType.Drive d = base.drive();
        double mmPerPulse = d.mmPerPulse();
        double wheelBase = d.wheelBaseMm();
        double unit = d.mmPerSecondPerUnit();
        double rightOverLeft = 1;
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
                case "base" -> {
                    if (!v.equals("khepera1")) {
                        throw new RobotFileException(source, n + 1,
                                "base " + v + ": only khepera1 calibrations are read"
                                + " in this version");
                    }
                }
                case "drive.mmPerPulse" -> mmPerPulse = number(source, n, v, 0.001, 10);
                case "drive.wheelBaseMm" -> wheelBase = number(source, n, v, 1, 1000);
                case "drive.mmPerSecondPerUnit" -> unit = number(source, n, v, 0.001, 1000);
                case "motor.rightOverLeft" -> rightOverLeft = number(source, n, v, 0.5, 2);
                case "reflect.cap" -> cap = number(source, n, v, 0, 10);
                case "reflect.robot" -> other = number(source, n, v, 0, 10);
                case "samples", "lamp" -> {
                    // the raw readings and the lamp series are kept for people; the engine's lamps take no table
                }
                default -> throw new RobotFileException(source, n + 1, "'" + kv[0] + "': the keys are robot, date,"
                        + " base, wall, samples, drive.*, motor.rightOverLeft, reflect.cap, reflect.robot and lamp");
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
        Path wallFile = file.toAbsolutePath().getParent().resolve(wall);
        SampleFit.Result fit;
        try {
            fit = SampleFit.fit(base, SampleResponses.samples(SampleTable.read(wallFile), base));
        } catch (java.io.IOException e) {
            throw new RobotFileException(source, 0, "its wall file " + wallFile + " cannot be read (" + e.getMessage()
                    + "): keep the .sample file 'khepera-link calibrate' wrote beside it");
        }
        List<Double> gains = new ArrayList<>();
        for (double g : fit.gains()) {
            gains.add(StrictMath.min(10, g));
        }
        RobotType.Measured measured = new RobotType.Measured(robot, date, gains, 2 / (1 + rightOverLeft),
                2 * rightOverLeft / (1 + rightOverLeft), cap, other);
        RobotType type = base.calibrated("calibration of " + robot + " on " + date + " (" + file.getFileName() + ")",
                wheelBase, unit, mmPerPulse, fit.table(), fit.offset(), fit.noiseAbs(), fit.noiseRel(), measured);
        return new Calibration(robot, date, type, fit);
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
