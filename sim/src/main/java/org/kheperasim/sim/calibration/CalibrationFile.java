package org.kheperasim.sim.calibration;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.robot.SampleFit;
import org.kheperasim.sim.engine.robot.SampleResponses;
import org.kheperasim.sim.engine.robot.SampleTable;

/**
 * Reads a calibration file ({@code khepera-calibration 1}, written by {@code khepera-link calibrate};
 * docs/calibration.md) onto its base robot type: the wall file's readings fitted into the proximity
 * table, offset and noise ({@link SampleFit}), the wheels' measured numbers into the drive, and
 * what a type cannot hold (each sensor's gain, each wheel's calibration) into settings. A
 * calibration is one robot measured: the per-robot spreads drawn for an unknown robot are set to 0.
 *
 * @param robot the robot's name
 * @param date the day it was measured
 * @param type the calibrated type
 * @param settings the settings that go with it (on top of the given ones)
 * @param fit the fitted proximity response
 */
public record CalibrationFile(String robot, String date, RobotType type, Settings settings, SampleFit.Result fit) {
    /** The first line of a calibration file. */
    public static final String MAGIC = "khepera-calibration 1";

    /**
     * @param file a calibration file
     * @param base the settings to add to
     * @return it, loaded
     * @throws IOException if a file cannot be read
     * @throws IllegalArgumentException (one line naming the file, the line and the fix) if it is malformed
     */
    public static CalibrationFile load(Path file, Settings base) throws IOException {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException("calibration " + file + " does not exist: give the .calibration file"
                    + " 'khepera-link calibrate' wrote");
        }
        if (lines.isEmpty() || !lines.get(0).trim().equals(MAGIC)) {
            throw new IllegalArgumentException("calibration " + file + " line 1 is not '" + MAGIC
                    + "': give the .calibration file 'khepera-link calibrate' wrote");
        }
        String robot = null;
        String date = null;
        String wall = null;
        RobotType baseType = RobotTypes.KHEPERA1;
        RobotType.Drive d = baseType.drive();
        double mmPerPulse = d.mmPerPulse();
        double wheelBase = d.wheelBaseMm();
        double unit = d.mmPerSecondPerUnit();
        double rightOverLeft = 1;
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
                        throw bad(file, n, "base " + v, "only khepera1 calibrations are read in this version");
                    }
                }
                case "drive.mmPerPulse" -> mmPerPulse = number(file, n, v, 0.001, 10);
                case "drive.wheelBaseMm" -> wheelBase = number(file, n, v, 1, 1000);
                case "drive.mmPerSecondPerUnit" -> unit = number(file, n, v, 0.001, 1000);
                case "motor.rightOverLeft" -> rightOverLeft = number(file, n, v, 0.5, 2);
                case "samples", "lamp" -> {
                    // the raw readings and the lamp series are kept for people; the engine's lamps take no table
                }
                default -> throw bad(file, n, "'" + kv[0] + "'", "the keys are robot, date, base, wall, samples, drive.*,"
                        + " motor.rightOverLeft and lamp");
            }
        }
        if (robot == null || date == null || wall == null) {
            throw bad(file, lines.size(), "lacks robot, date or wall", "a calibration names its robot, its date and its wall file");
        }
        Path wallFile = file.toAbsolutePath().getParent().resolve(wall);
        SampleFit.Result fit = SampleFit.fit(baseType, SampleResponses.samples(SampleTable.read(wallFile), baseType));
        RobotType type = baseType.calibrated("calibration of " + robot + " on " + date + " (" + file.getFileName() + ")",
                wheelBase, unit, mmPerPulse, fit.table(), fit.offset(), fit.noiseAbs(), fit.noiseRel());
        Settings s = base.with("prox.offsetSpread", "0").with("prox.gainSpread", "0").with("motor.spread", "0")
                .with("encoder.mmPerPulse", fmt(mmPerPulse))
                .with("motor.left.calibration", fmt(2 / (1 + rightOverLeft)))
                .with("motor.right.calibration", fmt(2 * rightOverLeft / (1 + rightOverLeft)));
        double[] g = fit.gains();
        for (int i = 0; i < g.length && i < Settings.PER_SENSOR; i++) {
            s = s.with("prox." + i + ".gain", fmt(StrictMath.min(10, g[i])));
        }
        return new CalibrationFile(robot, date, type, s, fit);
    }

    private static double number(Path file, int n, String v, double min, double max) {
        try {
            double x = Double.parseDouble(v);
            if (x >= min && x <= max) {
                return x;
            }
        } catch (NumberFormatException e) {
            // below
        }
        throw bad(file, n, "value '" + v + "'", "give a number in " + fmt(min) + ".." + fmt(max));
    }

    private static IllegalArgumentException bad(Path file, int n, String what, String fix) {
        return new IllegalArgumentException(String.format(Locale.ROOT, "calibration %s line %d: %s: %s", file, n + 1, what, fix));
    }

    private static String fmt(double v) {
        return String.format(Locale.ROOT, "%.6f", v);
    }
}
