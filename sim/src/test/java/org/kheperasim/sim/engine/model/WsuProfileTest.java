package org.kheperasim.sim.engine.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.space.World;

/**
 * The {@code wsu} profile's numbers, measured on the engine as a controller would see them: the
 * original's proximity response (issue 38: the front pair 1023 with the robot's centre 38 mm from a
 * wall it faces, the 45-degree sensors 452 there and 890 at 28 mm, a side sensor blind beyond about
 * 70 mm from the centre) and equal wheel speeds that drive straight. Runs without the course code.
 */
class WsuProfileTest {
    private static final Settings WSU = Settings.defaults().with("profile", "wsu");
    /** A wall face on a cell boundary. */
    private static final double FACE = 300 * OccupancyGrid.CELL_MM;

    /** A robot facing a vertical wall, its centre {@code centreMm} from the wall's face; its readings after 1 s. */
    private static int[] facing(double centreMm, Settings settings) {
        String text = String.format(Locale.ROOT, "khepera-arena 1\nname wall\nsize 1219.2 1219.2\nrobot %s 600 0\n"
                + "wall %s 400 %s 800 8\n", FACE - centreMm, FACE + 4, FACE + 4);
        return readings(text, new Pose(FACE - centreMm, 600, 0), settings);
    }

    /** A robot beside a horizontal wall on its left, its centre {@code centreMm} from the face. */
    private static int[] beside(double centreMm) {
        String text = String.format(Locale.ROOT, "khepera-arena 1\nname wall\nsize 1219.2 1219.2\nrobot 600 %s 0\n"
                + "wall 300 %s 900 %s 8\n", FACE - centreMm, FACE + 4, FACE + 4);
        return readings(text, new Pose(600, FACE - centreMm, 0), WSU);
    }

    private static int[] readings(String arena, Pose start, Settings settings) {
        Engine engine = new Engine(new World(ArenaFormat.parse(arena, "wall.arena")), 7);
        SimRobot robot = engine.addRobot("r", start, settings);
        engine.runUntil(1_000_000_000L);
        int[] out = new int[8];
        for (int i = 0; i < 8; i++) {
            out[i] = robot.controls().visibleProximity(i);
        }
        return out;
    }

    @Test
    void theProfileIsTheWsuRobotFileAndItsSettings() {
        Engine engine = new Engine(new World(ArenaFormat.parse("khepera-arena 1\nname open\nsize 1000 1000\n"
                + "robot 500 500 0\n", "open.arena")), 1);
        SimRobot robot = engine.addRobot("r", new Pose(500, 500, 0), WSU);
        assertSame(RobotTypes.WSU, robot.type());
        assertEquals("0", robot.settings().raw("noise.reading"));
        assertEquals("legacy", robot.settings().raw("wsu.speedUnits"));
        assertEquals("legacy", robot.settings().raw("wsu.positionUnits"));
        assertEquals("1", WSU.with("noise.reading", "1").raw("noise.reading"), "a setting given explicitly wins");
        SimRobot plain = engine.addRobot("p", new Pose(300, 300, 0), Settings.defaults());
        assertSame(RobotTypes.KHEPERA1, plain.type(), "the default stays the real robot");
        assertEquals("1", plain.settings().raw("noise.reading"));
    }

    @Test
    void theFrontSensorsSaturateFrom38Millimetres() {
        int[] at38 = facing(38, WSU);
        assertEquals(1023, at38[2], "front-left at 38 mm");
        assertEquals(1023, at38[3], "front-right at 38 mm");
        int[] at28 = facing(28, WSU);
        assertEquals(1023, at28[2]);
        // The real robot's response reads far less there: the profile is what makes the difference.
        assertTrue(facing(38, Settings.defaults().withNoise(0))[2] < 900, "khepera1 at 38 mm");
    }

    @Test
    void theFortyFiveDegreeSensorsReadTheOriginalsValues() {
        int[] at38 = facing(38, WSU);
        int[] at28 = facing(28, WSU);
        for (int s : new int[] {1, 4}) {
            assertEquals(452, at38[s], 15, "sensor " + s + " at 38 mm");
            assertEquals(890, at28[s], 15, "sensor " + s + " at 28 mm");
        }
    }

    @Test
    void theSideRaysEndAbout70MillimetresFromTheCentre() {
        int offset = (int) RobotTypes.WSU.proximity().offset();
        assertTrue(beside(66)[0] > offset + 10, "left sensor sees a wall 66 mm from the centre: " + beside(66)[0]);
        assertEquals(offset, beside(72)[0], "and nothing 72 mm away");
        assertEquals(offset, beside(78)[0], "a wall 78 mm away, where the real robot's sensor reads it");
    }

    @Test
    void equalWheelSpeedsDriveStraight() {
        String open = "khepera-arena 1\nname open\nsize 3000 1000\nrobot 100 500 0\n";
        Engine engine = new Engine(new World(ArenaFormat.parse(open, "open.arena")), 1);
        SimRobot wsu = engine.addRobot("wsu", new Pose(100, 300, 0), WSU);
        SimRobot real = engine.addRobot("real", new Pose(100, 700, 0), Settings.defaults());
        wsu.controls().commandSpeeds(0, 5, 5);
        real.controls().commandSpeeds(0, 5, 5);
        engine.runUntil(10_000_000_000L);
        assertEquals(0.0, wsu.headingDeg(), 0.0, "the original's heading stays exactly 0");
        assertEquals(300.0, wsu.y(), 0.0);
        assertTrue(wsu.x() > 450, "it drove: " + wsu.x());
        assertNotEquals(0.0, real.headingDeg(), "the real robot's wheels differ a little");
    }

    /**
     * The original's reading noise, measured where its robot stood still (docs/wsu-migration.md): off
     * under the profile, and with {@code noise.reading=1} proximity σ ≈ 2 counts + 6 % of the reading,
     * light σ ≈ 2.6 % of the reading even in darkness, while the wheels stay exact.
     */
    @Test
    void withReadingNoiseOnTheOriginalsNoiseIsThere() {
        String text = String.format(Locale.ROOT, "khepera-arena 1\nname wall\nsize 1219.2 1219.2\nrobot %s 600 0\n"
                + "wall %s 400 %s 800 8\n", FACE - 38, FACE + 4, FACE + 4);
        for (Settings s : new Settings[] {WSU, WSU.with("noise.reading", "1")}) {
            Engine engine = new Engine(new World(ArenaFormat.parse(text, "wall.arena")), 3);
            SimRobot robot = engine.addRobot("r", new Pose(FACE - 38, 600, 0), s);
            double[][] prox = new double[2][200];
            double[] light = new double[200];
            for (int k = 0; k < 200; k++) {
                engine.runUntil(1_000_000_000L + k * 100_000_000L);
                prox[0][k] = robot.controls().visibleProximity(1);
                prox[1][k] = robot.controls().visibleProximity(6);
                light[k] = robot.controls().visibleLight(0);
            }
            boolean on = s != WSU;
            double[] p45 = meanSd(prox[0]);
            double[] back = meanSd(prox[1]);
            double[] dark = meanSd(light);
            if (!on) {
                assertEquals(0, p45[1] + back[1] + dark[1], 0.0, "no noise under the profile");
                continue;
            }
            assertEquals(0.06, p45[1] / p45[0], 0.02, "45-degree sensor at " + p45[0] + ": sd " + p45[1]);
            assertEquals(2, back[1], 1.2, "a back sensor seeing nothing: sd " + back[1]);
            assertEquals(500, dark[0], 10, "light in darkness");
            assertEquals(0.026, dark[1] / dark[0], 0.008, "light noise in darkness: sd " + dark[1]);
        }
    }

    private static double[] meanSd(double[] v) {
        double m = Arrays.stream(v).average().orElseThrow();
        double ss = Arrays.stream(v).map(x -> (x - m) * (x - m)).sum();
        return new double[] {m, Math.sqrt(ss / v.length)};
    }
}
