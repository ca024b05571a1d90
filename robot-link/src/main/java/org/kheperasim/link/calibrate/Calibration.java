package org.kheperasim.link.calibrate;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * One robot's dated calibration and the files it is written to (docs/calibration.md):
 * {@code NAME-DATE.calibration} (the overlay on the robot's type that {@code khepera-sim} loads),
 * {@code NAME-DATE-wall.sample} (the wall series' means in the evorobotpy {@code .sample} format)
 * and {@code NAME-DATE-samples.csv} (every raw reading).
 *
 * @param robot the robot's name
 * @param date the day it was measured, ISO (2026-12-02)
 * @param base the robot type it overlays ({@code khepera1}, {@code khepera2}) and its nominal numbers
 * @param drive the wheels' measured numbers
 * @param wall the wall series
 * @param objects how much a cap and another robot reflect, the wall being 1
 * @param lampMm the lamp series' distances, mm
 * @param lamp the lamp series' mean ambient readings, {@code [distance][sensor]}
 * @param raw every raw reading, as CSV lines
 */
public record Calibration(String robot, String date, RobotBase base, Drive drive, Wall wall, Objects objects,
        double[] lampMm,
        double[][] lamp,
        List<String> raw) {
    /** The first line of a calibration file. */
    public static final String MAGIC = "khepera-calibration 1";

    /**
     * @param mmPerPulse wheel travel per encoder pulse, mm (straight run and ruler)
     * @param wheelBaseMm distance between the wheels, mm (spin and the angle turned)
     * @param mmPerSecondPerUnit wheel speed of one speed unit, mm/s (timed run, encoders)
     * @param rightOverLeft the right wheel's travel over the left's at equal commands (the run's drift by ruler)
     */
    public record Drive(double mmPerPulse, double wheelBaseMm, double mmPerSecondPerUnit, double rightOverLeft) {
    }

    /**
     * @param startMm the first block's gap between the robot's front and the wall, mm
     * @param stepMm the step it backs away by, mm
     * @param headings headings per block, evenly round the circle (the wall 360/headings degrees further right each)
     * @param means {@code [block][heading][sensor]} mean readings
     */
    public record Wall(double startMm, double stepMm, int headings, double[][][] means) {
        /** @param block a block @return its gap, mm */
        public double gapMm(int block) {
            return startMm + block * stepMm;
        }

        /** @param s a sensor @return its reading with the wall ahead at the farthest block: its floor */
        public double floor(int s) {
            return means[means.length - 1][0][s];
        }

        /** @param gap a gap, mm @param s a sensor @return its reading with the wall ahead at that gap, interpolated */
        public double aheadAt(double gap, int s) {
            double t = (gap - startMm) / stepMm;
            int b = (int) StrictMath.floor(StrictMath.max(0, StrictMath.min(means.length - 1, t)));
            int c = StrictMath.min(means.length - 1, b + 1);
            double f = StrictMath.max(0, StrictMath.min(1, t - b));
            return means[b][0][s] + f * (means[c][0][s] - means[b][0][s]);
        }
    }

    /**
     * @param capReflectance how much a cap reflects, the wall being 1 (NaN: not measured)
     * @param robotReflectance how much another robot's body reflects, the wall being 1 (NaN: not measured)
     * @param capMm the cap series' gaps, mm
     * @param cap its mean readings, {@code [gap][sensor]}
     * @param robotMm the robot series' gaps, mm
     * @param robot its mean readings
     */
    public record Objects(double capReflectance, double robotReflectance, double[] capMm, double[][] cap,
            double[] robotMm, double[][] robot) {
        /** Reflectances only, no series. */
        public Objects(double capReflectance, double robotReflectance) {
            this(capReflectance, robotReflectance, new double[0], new double[0][], new double[0], new double[0][]);
        }
    }

    /** @param dir where to write @return the calibration file written (the other two beside it) */
    public Path write(Path dir) throws IOException {
        Files.createDirectories(dir);
        String stem = robot + "-" + date;
        Path sample = dir.resolve(stem + "-wall.sample");
        Files.writeString(sample, sampleText(), StandardCharsets.UTF_8);
        Path csv = dir.resolve(stem + "-samples.csv");
        List<String> lines = new ArrayList<>();
        StringBuilder head = new StringBuilder("series,block,gap_mm,object_right_deg,repeat");
        for (int i = 0; i < base.sensors(); i++) {
            head.append(",s").append(i);
        }
        lines.add(head.toString());
        lines.addAll(raw);
        Files.write(csv, lines, StandardCharsets.UTF_8);
        Path cal = dir.resolve(stem + ".calibration");
        StringBuilder sb = new StringBuilder(MAGIC).append('\n');
        sb.append("# measured over robot-link by 'khepera-link calibrate'; docs/calibration.md\n");
        sb.append("robot ").append(robot).append('\n');
        sb.append("date ").append(date).append('\n');
        sb.append("base ").append(base.name()).append('\n');
        sb.append("wall ").append(sample.getFileName()).append('\n');
        sb.append("samples ").append(csv.getFileName()).append('\n');
        sb.append(String.format(Locale.ROOT,
                "drive.mmPerPulse %.5f%ndrive.wheelBaseMm %.3f%ndrive.mmPerSecondPerUnit %.4f%n"
                + "motor.rightOverLeft %.5f%n", drive.mmPerPulse(), drive.wheelBaseMm(), drive.mmPerSecondPerUnit(),
                drive.rightOverLeft()));
        if (!Double.isNaN(objects.capReflectance())) {
            sb.append(String.format(Locale.ROOT, "reflect.cap %.4f\n", objects.capReflectance()));
        }
        if (!Double.isNaN(objects.robotReflectance())) {
            sb.append(String.format(Locale.ROOT, "reflect.robot %.4f\n", objects.robotReflectance()));
        }
        series(sb, "cap.series", objects.capMm(), objects.cap());
        series(sb, "robot.series", objects.robotMm(), objects.robot());
        series(sb, "lamp", lampMm, lamp);
        Files.writeString(cal, sb.toString(), StandardCharsets.UTF_8);
        return cal;
    }

    /** One line per distance: the key, the distance (mm), each sensor's mean reading. */
    private static void series(StringBuilder sb, String key, double[] mm, double[][] means) {
        for (int d = 0; d < mm.length; d++) {
            sb.append(String.format(Locale.ROOT, "%s %.1f", key, mm[d]));
            for (double v : means[d]) {
                sb.append(String.format(Locale.ROOT, " %.1f", v));
            }
            sb.append('\n');
        }
    }

    private String sampleText() {
        int blocks = wall.means().length;
        int sensors = wall.means()[0][0].length;
        StringBuilder sb = new StringBuilder(
                String.format(Locale.ROOT, "%d %d %d %s %s%n", sensors, wall.headings(), blocks,
                Answers.fmt(wall.startMm()), Answers.fmt(wall.stepMm())));
        for (int t = 0; t < blocks; t++) {
            sb.append("TURN ").append(t).append('\n');
            for (int k = 0; k < wall.headings(); k++) {
                for (int s = 0; s < sensors; s++) {
                    double a = StrictMath.max(0, StrictMath.min(1, wall.means()[t][k][s] / base.fullScale()));
                    sb.append(String.format(Locale.ROOT, "%.6f ", a));
                }
                sb.append('\n');
            }
        }
        return sb.append("END\n").toString();
    }

    /**
     * Reads back the wall means at heading 0 of a written calibration ({@code --check} compares them).
     *
     * @param calibration a calibration file
     * @return the means with the wall straight ahead, block by block
     */
    public static Ahead ahead(Path calibration) throws IOException {
        List<String> lines = Files.readAllLines(calibration, StandardCharsets.UTF_8);
        if (lines.isEmpty() || !lines.get(0).trim().equals(MAGIC)) {
            throw new IllegalArgumentException("calibration " + calibration + " does not start with '" + MAGIC
                    + "': give a file written by 'khepera-link calibrate'");
        }
        String wallName = null;
        double mmPerPulse = Double.NaN;
        RobotBase base = RobotBase.KHEPERA1;
        for (String l : lines) {
            if (l.startsWith("base ")) {
                base = RobotBase.of(org.kheperasim.link.protocol.dialect.Dialect.named(l.substring(5).trim()));
            } else if (l.startsWith("wall ")) {
                wallName = l.substring(5).trim();
            } else if (l.startsWith("drive.mmPerPulse ")) {
                mmPerPulse = Double.parseDouble(l.substring(17).trim());
            }
        }
        if (Double.isNaN(mmPerPulse)) {
            mmPerPulse = base.mmPerPulse();
        }
        if (wallName == null) {
            throw new IllegalArgumentException("calibration " + calibration
                    + " names no wall file: add a line 'wall FILE.sample'");
        }
        Path p = calibration.toAbsolutePath().getParent().resolve(wallName);
        List<String> s = Files.readAllLines(p, StandardCharsets.UTF_8);
        String[] head = s.get(0).trim().split("\\s+");
        int ns = Integer.parseInt(head[0]);
        int na = Integer.parseInt(head[1]);
        int nd = Integer.parseInt(head[2]);
        double init = Double.parseDouble(head[3]);
        double step = Double.parseDouble(head[4]);
        double[] gaps = new double[nd];
        double[][] v = new double[nd][ns];
        for (int t = 0; t < nd; t++) {
            gaps[t] = init + t * step;
            String[] row = s.get(1 + t * (na + 1) + 1).trim().split("\\s+");
            for (int i = 0; i < ns; i++) {
                v[t][i] = Double.parseDouble(row[i]) * base.fullScale();
            }
        }
        return new Ahead(gaps, v, mmPerPulse);
    }

    /**
     * @param gapsMm the blocks' gaps, mm
     * @param means {@code [block][sensor]} with the wall straight ahead
     * @param mmPerPulse the calibrated wheel travel per pulse, mm
     */
    public record Ahead(double[] gapsMm, double[][] means, double mmPerPulse) {
    }
}
