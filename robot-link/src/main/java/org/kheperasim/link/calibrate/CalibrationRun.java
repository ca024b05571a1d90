package org.kheperasim.link.calibrate;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.session.SessionException;

/**
 * The guided procedure, step by step on the console: the wheels (a straight run measured by ruler,
 * a spin measured by the angle turned, a timed run read from the encoders), then the white wall
 * (facing it, backing away in encoder-measured steps, turning on the spot through every heading at
 * each step, ~20 readings per sensor per heading at the robot's 20 ms scan), then the lamp at a few
 * distances, a cap and another robot straight ahead at a few gaps (how much less than the wall they
 * reflect). For the robot's nominal numbers ({@link RobotBase}: Khepera I and II; it moves by position
 * commands, C, which the e-puck lacks).
 */
public final class CalibrationRun {

    /**
     * The procedure's sizes.
     *
     * @param readings readings per sensor per point (~20)
     * @param scanMillis time between readings (the robot's scan, 20 ms; 0 in tests)
     * @param blocks wall distances
     * @param headings headings per wall distance, evenly round the circle
     * @param runPulses pulses of the straight run
     * @param spinPulses pulses per wheel of the spin
     */
    public record Plan(int readings, long scanMillis, int blocks, int headings, int runPulses, int spinPulses) {
        /** @return the procedure of docs/calibration.md */
        public static Plan standard() {
            return new Plan(20, 20, 14, 24, 2500, 2081);
        }
    }

    private final Session session;
    private final Answers answers;
    private final PrintWriter out;
    private final Plan plan;
    private final RobotMoves moves;
    private final RobotBase base;
    private final List<String> raw = new ArrayList<>();

    /** @param session an open session @param answers the person @param out the console @param plan its sizes */
    public CalibrationRun(Session session, Answers answers, PrintWriter out, Plan plan) {
        this(session, answers, out, plan, RobotBase.of(session.dialect()));
    }

    /**
     * @param session an open session
     * @param answers the person
     * @param out the console
     * @param plan its sizes
     * @param base the robot's nominal numbers (its type's)
     */
    public CalibrationRun(Session session, Answers answers, PrintWriter out, Plan plan, RobotBase base) {
        this.base = base;
        this.session = session;
        this.answers = answers;
        this.out = out;
        this.plan = plan;
        this.moves = new RobotMoves(session, plan.scanMillis());
    }

    /**
     * @param robot the robot's name
     * @param date the day, ISO
     * @return the calibration measured
     */
    public Calibration run(String robot, String date) throws SessionException {
        Calibration.Drive drive = wheels();
        Calibration.Wall wall = wall(drive);
        List<double[]> capSeries = new ArrayList<>();
        double cap = reflectance("cap", "a bottle cap (the arena's caps)", wall, capSeries);
        List<double[]> robotSeries = new ArrayList<>();
        double other = reflectance("robot", "another robot of the lab (switched off)", wall, robotSeries);
        double[] lampMm = lampDistances();
        double[][] lamp = new double[lampMm.length][];
        for (int d = 0; d < lampMm.length; d++) {
            answers.pause("lamp." + d,
                    String.format(Locale.ROOT, "Lamp: put the lamp straight ahead of the robot, its bulb"
                    + " %.0f mm from the robot's front (by ruler), nothing else lit;", lampMm[d]));
            int[][] r = moves.readings(true, plan.readings());
            record("lamp", d, lampMm[d], 0, r);
            lamp[d] = RobotMoves.mean(r);
        }
        session.exchange(session.dialect().setSpeeds(0, 0));
        say("Done: the robot is stopped.");
        return new Calibration(robot, date, base, drive, wall, new Calibration.Objects(cap, other,
                distances(capSeries), means(capSeries), distances(robotSeries), means(robotSeries)), lampMm, lamp,
                List.copyOf(raw));
    }

    private Calibration.Drive wheels() throws SessionException {
        say("Step 1 of 3, the wheels. You need a ruler (mm) and a protractor, and 300 mm of clear floor ahead.");
        answers.pause("run.start", "Mark the floor under the middle of the wheel axle and the robot's heading;");
        moves.moveBy(plan.runPulses(), plan.runPulses());
        double runMm = answers.number("run.mm", "Measure by ruler how far the axle's mark moved, mm",
                plan.runPulses() * base.mmPerPulse());
        double sideMm = answers.number("run.sideMm", "Measure how far the axle ended to the LEFT of the straight line"
                + " (negative: to the right), mm", 0);
        double mmPerPulse = runMm / plan.runPulses();
        answers.pause("spin.start", "Mark the robot's heading on the floor;");
        moves.moveBy(-plan.spinPulses(), plan.spinPulses());
        double spinDeg = answers.number("spin.deg", "Measure the angle the robot turned to the left, degrees (a full"
                + " turn is 360)", StrictMath.toDegrees(
                        2 * plan.spinPulses() * base.mmPerPulse() / base.wheelBaseMm()));
        double wheelBase = 2 * plan.spinPulses() * mmPerPulse / StrictMath.toRadians(spinDeg);
        // Curving by sideMm over runMm turns the heading by 2 side / run; the wheels differ by that times the base.
        double turn = 2 * sideMm / runMm;
        double rightOverLeft = (runMm + turn * wheelBase / 2) / (runMm - turn * wheelBase / 2);
        int speed = 10;
        long millis = 2000;
        int[] d = moves.run(speed, millis);
        double unit = (d[0] + d[1]) / 2.0 * mmPerPulse / (millis / 1000.0) / speed;
        say(String.format(Locale.ROOT,
                "wheels: %.5f mm per pulse, wheel base %.2f mm, %.3f mm/s per speed unit, right/left %.4f",
                mmPerPulse, wheelBase, unit, rightOverLeft));
        return new Calibration.Drive(mmPerPulse, wheelBase, unit, rightOverLeft);
    }

    private Calibration.Wall wall(Calibration.Drive drive) throws SessionException {
        double start = answers.number("wall.startMm", "Step 2 of 3, the white wall. Put the robot facing a white wall"
                + " straight on; the gap between the robot's front and the wall, by ruler, mm", 5);
        double step = answers.number("wall.stepMm", "The step the robot backs away by, mm", 3);
        answers.pause("wall.placed", "Leave the robot there, nothing else within 100 mm of it;");
        int h = plan.headings();
        double[][][] means = new double[plan.blocks()][h][];
        int stepPulses = (int) StrictMath.rint(step / drive.mmPerPulse());
        for (int t = 0; t < plan.blocks(); t++) {
            int[] base = moves.counters();
            for (int k = 0; k < h; k++) {
                // Turn to the left on the spot: the wall then lies k * 360 / h degrees to the robot's right.
                int p = (int) StrictMath.rint(
                        StrictMath.toRadians(k * 360.0 / h) * drive.wheelBaseMm() / 2 / drive.mmPerPulse());
                moves.moveTo(base[0] - p, base[1] + p);
                int[][] r = moves.readings(false, plan.readings());
                record("wall", t, start + t * step, k * 360.0 / h, r);
                means[t][k] = RobotMoves.mean(r);
            }
            int full = (int) StrictMath.rint(2 * StrictMath.PI * drive.wheelBaseMm() / 2 / drive.mmPerPulse());
            moves.moveTo(base[0] - full, base[1] + full);
            if (t + 1 < plan.blocks()) {
                moves.moveBy(-stepPulses, -stepPulses);
            }
            say(String.format(Locale.ROOT, "wall at %.1f mm: front sensors read %.0f and %.0f", start + t * step,
                    means[t][0][2], means[t][0][3]));
        }
        return new Calibration.Wall(start, step, h, means);
    }

    /**
     * An object straight ahead at a few gaps: its front readings against the wall's at the same gaps.
     *
     * @return how much it reflects, the wall being 1 (the median of the ratios where the wall reads
     *     well above its floor); NaN when the person skips it
     */
    private double reflectance(String kind, String what, Calibration.Wall wall, List<double[]> series)
            throws SessionException {
        double[] gaps = distances(kind + ".distances", "The " + kind + " series: put " + what + " straight ahead;"
                + " its gaps from the robot's front, mm, comma-separated (none: skip)", "5,10,15,20");
        List<Double> ratios = new ArrayList<>();
        for (int d = 0; d < gaps.length; d++) {
            answers.pause(kind + ".placed." + d, String.format(Locale.ROOT, "Put %s straight ahead of the robot, its"
                    + " near side %.0f mm from the robot's front (by ruler), nothing else within 100 mm;",
                    what, gaps[d]));
            int[][] r = moves.readings(false, plan.readings());
            record(kind, d, gaps[d], 0, r);
            double[] m = RobotMoves.mean(r);
            double[] line = new double[m.length + 1];
            line[0] = gaps[d];
            System.arraycopy(m, 0, line, 1, m.length);
            series.add(line);
            for (int s = 2; s <= 3; s++) {
                double floor = wall.floor(s);
                double w = wall.aheadAt(gaps[d], s) - floor;
                if (w > 50) {
                    ratios.add(StrictMath.max(0, m[s] - floor) / w);
                }
            }
        }
        if (ratios.isEmpty()) {
            if (gaps.length > 0) {
                say("the " + kind + " series: the wall reads too little at those gaps to compare; give nearer ones");
            }
            return Double.NaN;
        }
        java.util.Collections.sort(ratios);
        double median = ratios.get(ratios.size() / 2);
        say(String.format(Locale.ROOT, "%s: reflects %.2f of the wall", kind, median));
        return median;
    }

    /** @return the series' distances, mm */
    private static double[] distances(List<double[]> series) {
        return series.stream().mapToDouble(l -> l[0]).toArray();
    }

    /** @return the series' mean readings, {@code [distance][sensor]} */
    private static double[][] means(List<double[]> series) {
        return series.stream().map(l -> java.util.Arrays.copyOfRange(l, 1, l.length)).toArray(double[][]::new);
    }

    private double[] lampDistances() {
        return distances("lamp.distances",
                "Step 3 of 3, the lamp. The lamp distances, mm, comma-separated (none: skip)",
                "50,100,200,400");
    }

    private double[] distances(String key, String prompt, String dflt) {
        String s = answers.ask(key, prompt, dflt);
        if (s.isBlank() || s.equals("none")) {
            return new double[0];
        }
        String[] p = s.split(",");
        double[] d = new double[p.length];
        for (int i = 0; i < p.length; i++) {
            try {
                d[i] = Double.parseDouble(p[i].trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("answer " + key + "=" + s + ": give mm like 50,100,200");
            }
        }
        return d;
    }

    private void record(String series, int block, double gapMm, double rightDeg, int[][] r) {
        for (int i = 0; i < r.length; i++) {
            StringBuilder sb = new StringBuilder(
                    String.format(Locale.ROOT, "%s,%d,%.2f,%.2f,%d", series, block, gapMm, rightDeg, i));
            for (int v : r[i]) {
                sb.append(',').append(v);
            }
            raw.add(sb.toString());
        }
    }

    private void say(String line) {
        out.println(line);
        out.flush();
    }

    /** @return the robot's moves and readings, for {@link DriftCheck} */
    RobotMoves moves() {
        return moves;
    }
}
