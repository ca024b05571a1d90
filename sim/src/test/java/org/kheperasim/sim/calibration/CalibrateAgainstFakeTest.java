package org.kheperasim.sim.calibration;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.link.cli.Main;
import org.kheperasim.link.fake.FakeKhepera;
import org.kheperasim.link.fake.FakeWallScene;
import org.kheperasim.link.fake.OnSocket;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.MeasuredTables;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.space.World;

/**
 * {@code khepera-link calibrate --non-interactive} against a fake Khepera whose sensors follow a
 * response the calibration is not told (warped per sensor by a gain and a distance shift drawn from
 * a seed, its wheels off nominal): the simulator loaded with the calibration reads what the fake
 * reads at gaps the calibration did not sample; {@code --check} passes on the same robot and fails
 * once its sensors drift by 20 %.
 */
class CalibrateAgainstFakeTest {
    private static final long SEED = 37;
    private static Shared shared;

    /** One calibration of the fake robot (seed {@value #SEED}), made once for the tests that only read it. */
    record Shared(FakeWallScene scene, Path calibration) {
    }

    /** @return the fake robot of seed {@value #SEED} and its calibration, made on the first call */
    static synchronized Shared shared() throws Exception {
        if (shared == null) {
            FakeWallScene scene = new FakeWallScene(SEED);
            shared = new Shared(scene, calibrate(scene, Files.createTempDirectory("khepera-calibration-")));
        }
        return shared;
    }
    private static final Settings QUIET = Settings.defaults().withNoise(0).with("prox.spikeRate", "0");

    @Test
    void theSimulatorLoadedWithTheCalibrationMatchesTheFake() throws Exception {
        FakeWallScene scene = shared().scene();
        Path cal = shared().calibration();
        Path dir = cal.getParent();
        assertTrue(Files.exists(dir.resolve("lab3-2026-12-02-wall.sample")));
        List<String> raw = Files.readAllLines(dir.resolve("lab3-2026-12-02-samples.csv"));
        assertEquals(1 + 14 * 24 * 20 + 2 * 4 * 20 + 4 * 20, raw.size(), "one line per raw reading, with its header");

        // The calibration is a robot file: the robot it measured.
        RobotType c = RobotTypes.load(cal);
        assertEquals("lab3", c.measured().robot());
        assertEquals("2026-12-02", c.measured().date());
        // The ruler measures the axle's middle: the two wheels' mean travel per pulse.
        assertEquals(scene.mmPerPulse() * (1 + scene.rightOverLeft()) / 2, c.drive().mmPerPulse(), 0.0002, "mm per pulse");
        assertEquals(scene.rightOverLeft(), c.measured().rightCalibration() / c.measured().leftCalibration(), 0.002,
                "right over left");
        assertEquals(scene.wheelBaseMm(), c.drive().wheelBaseMm(), 0.6, "wheel base");
        // A cap and another robot reflect what the fake's do, the wall being 1.
        assertEquals(scene.capReflectance(), c.measured().capReflectance(), 0.05, "cap reflectance");
        assertEquals(scene.robotReflectance(), c.measured().robotReflectance(), 0.05, "robot reflectance");
        // Each sensor measured on its own: its own table, its noise from the repeats (the fake's is 3 counts).
        MeasuredTables tables = c.measured().tables();
        assertEquals(8, tables.sensors().size(), "a wall table a sensor");
        assertEquals(1, tables.cap().size(), "the cap series' table");
        assertEquals(1, tables.robot().size(), "the robot series' table");
        assertEquals(3, c.proximity().noiseAbs(), 0.5, "the noise measured in the repeats");
        // The lamp series is the light sensors' response: a lamp where the series put none reads as on the fake.
        for (double lampMm : new double[] {75, 150, 300}) {
            int[] light = lit(c, lampMm);
            for (int i = 2; i <= 3; i++) {
                double fake = 480 - 460 / (1 + StrictMath.pow(lampMm / 60, 2));
                assertEquals(fake, light[i], 0.05 * 460, "sensor " + i + ", the lamp " + lampMm + " mm ahead");
            }
        }
        // Unsampled gaps: halfway between the calibration's 5, 8, 11, ... mm, at headings between its 15 degrees too.
        List<Double> errors = new ArrayList<>();
        List<Double> lit = new ArrayList<>();
        double worst = 0;
        for (double gap : new double[] {6.5, 9.5, 12.5, 15.5, 21.5, 27.5}) {
            for (double right : new double[] {0, 7.5, 37.5, 82.5, 277.5, 322.5}) {
                int[] sim = simulate(c, gap, right);
                for (int i = 0; i < 8; i++) {
                    double e = StrictMath.abs(sim[i] - scene.expected(i, gap, right));
                    errors.add(e);
                    if (scene.expected(i, gap, right) > 50) {
                        lit.add(e);
                    }
                    worst = StrictMath.max(worst, e);
                }
            }
        }
        double[] e = errors.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        double median = e[e.length / 2];
        double p90 = e[(int) (e.length * 0.9)];
        double[] l = lit.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        double medianLit = l[l.length / 2];
        System.out.printf(Locale.ROOT, "calibrated simulator vs fake at %d unsampled points: median %.1f, 90%% %.1f, worst %.1f counts;"
                + " the %d lit (> 50): median %.1f%n", e.length, median, p90, worst, l.length, medianLit);
        assertTrue(medianLit <= 0.05 * 1023, "median error of the lit readings " + medianLit);
        assertTrue(median <= 0.05 * 1023, "median error " + median);
        assertTrue(p90 <= 0.10 * 1023, "90th percentile error " + p90);
    }

    @Test
    void checkNoticesATwentyPercentDrift(@TempDir Path dir) throws Exception {
        FakeWallScene scene = new FakeWallScene(SEED + 1);
        Path cal = calibrate(scene, dir);
        assertEquals(0, check(scene, cal, 1.0), "the same robot has not drifted");
        assertEquals(1, check(scene, cal, 1.2), "20 % more signal is a drift");
        assertEquals(1, check(scene, cal, 0.8), "20 % less signal is a drift");
    }

    private static int check(FakeWallScene scene, Path cal, double drift) throws Exception {
        scene.drift(drift);
        scene.place(5, 0);
        StringWriter out = new StringWriter();
        int code;
        try (OnSocket<FakeKhepera> fake = fake(scene)) {
            code = Main.execute(new String[] {"calibrate", "--port", fake.url(), "--check", cal.toString(), "--non-interactive",
                "--scan-ms", "0", "--readings", "10"}, new ByteArrayInputStream(new byte[0]), new PrintWriter(out),
                new PrintWriter(new StringWriter()));
        }
        assertTrue(out.toString().contains("median change"), out.toString());
        return code;
    }

    /**
     * {@code khepera-link calibrate --non-interactive} on the fake, as a lab would run it unattended:
     * every measurement by ruler and protractor is given with {@code --answer}, and the "person" who
     * puts the robot before the wall, then a cap and another robot before it, is the console watcher
     * below: it acts when the procedure prints the step's question, before the robot reads.
     */
    static Path calibrate(FakeWallScene scene, Path dir) throws Exception {
        // What a person would measure by ruler and protractor on this robot.
        double runMm = 2500 * scene.mmPerPulse() * (1 + scene.rightOverLeft()) / 2;
        double spinDeg = StrictMath.toDegrees(2081 * scene.mmPerPulse() * (1 + scene.rightOverLeft()) / scene.wheelBaseMm());
        double turn = 2500 * scene.mmPerPulse() * (scene.rightOverLeft() - 1) / scene.wheelBaseMm();
        StringWriter all = new StringWriter();
        PrintWriter console = new PrintWriter(new java.io.Writer() {
            private final StringBuilder line = new StringBuilder();

            @Override
            public void write(char[] c, int off, int len) {
                all.write(c, off, len);
                for (int k = off; k < off + len; k++) {
                    line.append(c[k]);
                    String l = line.toString();
                    // The robot 5 mm from the wall, straight on; a cap, then a robot, at 5, 10, 15, 20 mm.
                    if (l.endsWith("(wall.placed): ")) {
                        scene.place(5, 0);
                    } else if (l.matches(".*\\(lamp\\.[0-9]+\\): $")) {
                        // The lamp at 50, 100, 200, 400 mm ahead of the robot's front.
                        int d = Integer.parseInt(l.substring(l.lastIndexOf('.') + 1, l.lastIndexOf(')')));
                        scene.setLampMm(50 * (1 << d));
                    } else if (l.matches(".*\\((cap|robot)\\.placed\\.[0-9]+\\): $")) {
                        String key = l.substring(l.lastIndexOf('(') + 1, l.lastIndexOf(')'));
                        int d = Integer.parseInt(key.substring(key.lastIndexOf('.') + 1));
                        scene.placeObject(5 + 5 * d, key.startsWith("cap") ? scene.capReflectance()
                                : scene.robotReflectance());
                    }
                    if (c[k] == '\n') {
                        line.setLength(0);
                    }
                }
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        }, true);
        try (OnSocket<FakeKhepera> fake = fake(scene)) {
            int code = Main.execute(new String[] {"calibrate", "--port", fake.url(), "--robot", "lab3", "--date",
                "2026-12-02", "--out", dir.toString(), "--non-interactive", "--scan-ms", "0",
                "--answer", String.format(Locale.ROOT, "run.mm=%.2f", runMm),
                "--answer", String.format(Locale.ROOT, "run.sideMm=%.2f", runMm * turn / 2),
                "--answer", String.format(Locale.ROOT, "spin.deg=%.2f", spinDeg)},
                    new ByteArrayInputStream(new byte[0]), console, console);
            assertEquals(0, code, all.toString());
        } finally {
            System.out.println(all.toString().lines().filter(l -> l.startsWith("wheels") || l.startsWith("wall at 5")
                    || l.contains(": reflects ")).reduce("", (a, b) -> a + b + "\n"));
        }
        return dir.resolve("lab3-2026-12-02.calibration");
    }

    /**
     * A real run on the fake robot, recorded by {@code khepera-link run --record}, compared with its
     * simulation: with the fake's calibration (its true wheels, its warped sensors measured) the two
     * paths stay together (at most half as far apart as with the default Khepera, which parts by 30 mm
     * within two seconds); and the
     * readings differ less in all (the front pair's RMS stays high either way: near the wall a reading
     * changes by tens of counts a millimetre, and the real run's polls lag its simulation's by some ms).
     */
    @Test
    void compareOnTheFakeRobotDivergesLessWithItsCalibration(@TempDir Path dir) throws Exception {
        FakeWallScene scene = shared().scene();
        Path cal = shared().calibration();
        // The robot faces the wall 40 mm away and Braitenberg drives it for 4 s: up to the wall and away.
        scene.place(40, 0);
        Path rec = dir.resolve("fake.rec");
        StringWriter out = new StringWriter();
        try (OnSocket<FakeKhepera> fake = fake(scene)) {
            int code = Main.execute(new String[] {"run", "--port", fake.url(), "--controller", "Braitenberg", "--seconds",
                "4", "--record", rec.toString()}, new ByteArrayInputStream(new byte[0]), new PrintWriter(out, true),
                    new PrintWriter(out, true));
            assertEquals(0, code, out.toString());
        }
        double face = 300 * OccupancyGrid.CELL_MM;
        Path arena = dir.resolve("wall.arena");
        Files.writeString(arena, String.format(Locale.ROOT, "khepera-arena 1\nname wall\nsize 1219.2 1219.2\n"
                + "robot %s 600 0\nwall %s 100 %s 1100 8\n", face - 27.5 - 40, face + 4, face + 4));
        String calibrated = compare(rec, arena, dir, "--calibration", cal.toString());
        String nominal = compare(rec, arena, dir.resolve("nominal"));
        System.out.println("fake robot, calibrated:\n" + calibrated + "nominal:\n" + nominal);
        // The real run is timed by the host's clock: on a loaded machine its commands reach the fake late, and
        // both comparisons part further (calibrated: 5 mm on an idle machine, 77 mm once in CI); the
        // calibrated one still parts far less than the nominal one (249 mm idle).
        assertTrue(nominal.contains("first more than 30.0 mm apart at"), nominal);
        assertTrue(apart(calibrated) * 2 < apart(nominal), calibrated + nominal);
        assertTrue(rmsSum(calibrated) < rmsSum(nominal), calibrated + nominal);
    }

    private static String compare(Path rec, Path arena, Path out, String... more) {
        List<String> args = new ArrayList<>(List.of("compare", rec.toString(), "--arena", arena.toString(), "--controller",
                "Braitenberg", "--out", out.toString()));
        args.addAll(List.of(more));
        org.kheperasim.testfixtures.Cli.Printed p = org.kheperasim.testfixtures.Cli.main(args.toArray(new String[0]));
        assertEquals(0, p.code(), p.out() + p.err());
        return p.out();
    }

    /** @return how far apart compare's two odometry paths come at most, mm */
    private static double apart(String report) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("the paths are at most ([0-9.]+) mm apart").matcher(report);
        assertTrue(m.find(), report);
        return Double.parseDouble(m.group(1));
    }

    /** @return the sum of compare's per-sensor RMS */
    private static double rmsSum(String report) {
        String line = report.lines().filter(l -> l.startsWith("per sensor RMS")).findFirst().orElseThrow();
        return Arrays.stream(line.substring(line.indexOf(':') + 1).trim().split(" ")).mapToDouble(Double::parseDouble).sum();
    }

    /** A fake Khepera on a loopback socket, in the scene. */
    private static OnSocket<FakeKhepera> fake(FakeWallScene scene) throws Exception {
        return OnSocket.start((in, o) -> {
            FakeKhepera k = new FakeKhepera(in, o, null);
            k.setScene(scene);
            return k.start();
        });
    }

    /** @return the ambient readings with a lamp {@code lampMm} ahead of the body */
    private static int[] lit(RobotType c, double lampMm) {
        World world = new World(ArenaFormat.parse(String.format(Locale.ROOT, "khepera-arena 1\nname lamp\n"
                + "size 1219.2 1219.2\nrobot 300 600 0\nlight %s 600 range 1000\n", 300 + 27.5 + lampMm), "lamp.arena"));
        Engine engine = new Engine(world, 7);
        SimRobot robot = engine.addRobot("r", new Pose(300, 600, 0), QUIET, c);
        for (int t = 0; t < 100; t++) {
            engine.step();
        }
        int[] out = new int[8];
        for (int i = 0; i < 8; i++) {
            out[i] = robot.controls().visibleLight(i);
        }
        return out;
    }

    private static int[] simulate(RobotType c, double gap, double right) {
        double face = 300 * OccupancyGrid.CELL_MM;
        double x = face - 27.5 - gap;
        World world = new World(ArenaFormat.parse(String.format(Locale.ROOT, "khepera-arena 1\nname wall\nsize 1219.2 1219.2\n"
                + "robot %s 600 0\nwall %s 300 %s 900 8\n", x, face + 4, face + 4), "wall.arena"));
        Engine engine = new Engine(world, 7);
        SimRobot robot = engine.addRobot("r", new Pose(x, 600, right), QUIET, c);
        for (int t = 0; t < 100; t++) {
            engine.step();
        }
        int[] out = new int[8];
        for (int i = 0; i < 8; i++) {
            out[i] = robot.controls().visibleProximity(i);
        }
        return Arrays.copyOf(out, 8);
    }
}
