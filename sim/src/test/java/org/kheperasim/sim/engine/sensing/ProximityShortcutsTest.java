package org.kheperasim.sim.engine.sensing;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.kheperasim.api.IrSensor;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Miscalibration;
import org.kheperasim.sim.engine.model.RobotModel;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.noise.CounterNoise;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.space.World;

/**
 * The proximity sensors' shortcuts change no reading: a sample with nothing in reach (the shapes'
 * clearance lattice, the nearest cap, the robots around), the walls and lamps taken from the
 * buckets around the robot and narrowed to each sensor's cone, caps and robots outside a cone left
 * out. Each bundled arena, with caps and other robots scattered over its floor, is sampled at random
 * poses (many of them close to a wall, a cap or a robot) both with the shortcuts and by brute force
 * (every beam cast against every wall, lamp and cap on the floor and the floor's edge, every robot
 * within reach looked at), with the same noise draws; the readings must be the same.
 */
class ProximityShortcutsTest {

    static List<String> arenas() {
        return ArenaFormat.bundledNames();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("arenas")
    void theShortcutsChangeNoReading(String name) {
        SplittableRandom random = new SplittableRandom(name.hashCode());
        Arena bare = ArenaFormat.resolve(name);
        DistanceField bareField = DistanceField.of(OccupancyGrid.of(bare));
        List<Cap> caps = new ArrayList<>(bare.caps());
        for (int k = 0; k < 40; k++) {
            double[] at = freeSpot(bare, bareField, random, Cap.DEFAULT_RADIUS + 1);
            // A quarter of them tiny.
            caps.add(k % 4 == 0 ? new Cap(at[0], at[1], random.nextDouble(0.2, OccupancyGrid.CELL_MM))
                    : new Cap(at[0], at[1]));
        }
        Arena arena = new Arena(bare.name(), bare.width(), bare.height(), bare.robots(), bare.walls(), bare.lights(),
                caps, bare.regions());
        World world = new World(arena);
        Engine engine = new Engine(world, 11);
        Settings settings = Settings.defaults();
        // Robot 0 is the one that samples (its own body does not count); the others stand about.
        engine.addRobot("sampler", new Pose(-100, -100, 0), settings);
        for (int k = 0; k < 30; k++) {
            double[] at = freeSpot(arena, world.field(), random, RobotTypes.KHEPERA1.body().radiusMm() + 1);
            engine.addRobot("r" + k, new Pose(at[0], at[1], random.nextDouble(360)), settings);
        }
        ProximitySensing quick = sensing(world, settings, 5);
        ProximitySensing slow = sensing(world, settings, 5);
        slow.withoutShortcuts();

        int[] a = new int[IrSensor.COUNT];
        int[] b = new int[IrSensor.COUNT];
        int seen = 0;
        for (int k = 0; k < 20_000; k++) {
            double[] at = k % 3 == 2 ? atTheEdgeOfACap(arena, world, engine, random)
                    : placeable(arena, world, engine, random, k % 3 == 1);
            if (at == null) {
                continue;
            }
            // At a cap's edge, half the time the front sensors face the cap.
            double heading = at.length > 2 && k % 2 == 0 ? at[2] + random.nextDouble(-0.3, 0.3)
                    : random.nextDouble(2 * StrictMath.PI);
            double c = StrictMath.cos(heading);
            double s = StrictMath.sin(heading);
            quick.sample(at[0], at[1], c, s, k, a);
            slow.sample(at[0], at[1], c, s, k, b);
            assertArrayEquals(b, a, () -> String.format(java.util.Locale.ROOT,
                    "%s: the readings at (%.3f, %.3f) heading %.2f rad", name, at[0], at[1], heading));
            for (int v : b) {
                if (v > 200) {
                    seen++;
                    break;
                }
            }
        }
        // The poses must put things in sight, or the comparison proves little.
        assertTrue(seen > 3000, name + ": only " + seen + " samples saw anything");
    }

    /**
     * A tiny cap at the very end of the sensors' reach: a robot stands at every distance (0.05 mm
     * apart) where its reach ends around the cap's disc, turned every way (1° apart); the shortcuts
     * must not leave out a cap that a beam's end just touches.
     */
    @org.junit.jupiter.api.Test
    void aCapAtTheEndOfTheSensorsReachIsSeen() {
        double cell = OccupancyGrid.CELL_MM;
        double capX = 200 * cell + 0.01;
        double capY = 200 * cell + 0.01;
        double radius = 0.3;
        Arena arena = new Arena("small-cap", 1219.2, 1219.2, List.of(new Pose(100, 100, 0)), List.of(), List.of(),
                List.of(new Cap(capX, capY, radius)), List.of());
        World world = new World(arena);
        Settings settings = Settings.defaults();
        ProximitySensing quick = sensing(world, settings, 3);
        ProximitySensing slow = sensing(world, settings, 3);
        slow.withoutShortcuts();
        double range = RobotModel.of(settings).proximity().profile().rangeMm();
        int[] a = new int[IrSensor.COUNT];
        int[] b = new int[IrSensor.COUNT];
        long k = 0;
        // From the upper right, where the far corner of the cap's cell is.
        double from = StrictMath.PI / 4;
        for (int step = 0; step <= 90; step++) {
            double extra = -0.5 + step * 0.05;
            double d = radius + RobotTypes.KHEPERA1.sensorReachMm() + range + extra;
            double x = capX + d * StrictMath.cos(from);
            double y = capY + d * StrictMath.sin(from);
            for (int degrees = 0; degrees < 360; degrees++) {
                double heading = StrictMath.toRadians(degrees);
                quick.sample(x, y, StrictMath.cos(heading), StrictMath.sin(heading), k, a);
                slow.sample(x, y, StrictMath.cos(heading), StrictMath.sin(heading), k, b);
                String where = String.format(java.util.Locale.ROOT,
                        "%.2f mm beyond the sensors' reach of the cap's disc, heading %d°", extra, degrees);
                assertArrayEquals(b, a, where);
                k++;
            }
        }
    }

    private static ProximitySensing sensing(World world, Settings settings, long key) {
        RobotModel model = RobotModel.of(settings);
        Miscalibration calibration = new Miscalibration(model, new CounterNoise(key));
        CounterNoise[] noise = new CounterNoise[IrSensor.COUNT];
        for (int i = 0; i < noise.length; i++) {
            noise[i] = new CounterNoise(key * 31 + i);
        }
        return new ProximitySensing(world, 0, new SensorPlacement(RobotTypes.KHEPERA1), model, calibration, noise);
    }

    /** A spot for a body of this radius: clear of walls and lamps, within the arena. */
    private static double[] freeSpot(Arena arena, DistanceField field, SplittableRandom random, double radius) {
        for (int tries = 0; tries < 10_000; tries++) {
            double x = random.nextDouble(arena.width());
            double y = random.nextDouble(arena.height());
            if (field.preciseClearance(x, y) >= radius) {
                return new double[] {x, y};
            }
        }
        throw new IllegalStateException("no free spot in " + arena.name());
    }

    /**
     * A robot centre whose sensors' reach ends just around a cap's edge, where the shortcuts' bound
     * of the nearest cap decides.
     *
     * @return the centre and the heading that faces the cap, or null when none was found
     */
    private static double[] atTheEdgeOfACap(Arena arena, World world, Engine engine, SplittableRandom random) {
        double range = RobotModel.of(Settings.defaults()).proximity().profile().rangeMm();
        for (int tries = 0; tries < 200; tries++) {
            int k = random.nextInt(world.capSet().count());
            double angle = random.nextDouble(2 * StrictMath.PI);
            double d = world.capSet().radius(k) + RobotTypes.KHEPERA1.sensorReachMm() + range
                    + random.nextDouble(-0.5, 1.5 * StrictMath.sqrt(2) * OccupancyGrid.CELL_MM);
            double x = world.capSet().x(k) + d * StrictMath.cos(angle);
            double y = world.capSet().y(k) + d * StrictMath.sin(angle);
            if (x > 0 && y > 0 && x < arena.width() && y < arena.height() && fits(world, engine, x, y)) {
                return new double[] {x, y, angle + StrictMath.PI};
            }
        }
        return null;
    }

    private static boolean fits(World world, Engine engine, double x, double y) {
        return clearance(world, engine, x, y) >= RobotTypes.KHEPERA1.body().radiusMm();
    }

    /** @return how far a robot centre at (x, y) is from the nearest wall, lamp, cap or other robot, mm */
    private static double clearance(World world, Engine engine, double x, double y) {
        double c = StrictMath.min(world.field().preciseClearance(x, y), world.capSet().nearestSurface(x, y));
        for (SimRobot r : engine.robots().subList(1, engine.robots().size())) {
            c = StrictMath.min(c, StrictMath.hypot(r.x() - x, r.y() - y) - RobotTypes.KHEPERA1.body().radiusMm());
        }
        return c;
    }

    /**
     * A robot centre where a robot can be: its body overlaps no wall, lamp, cap or other robot
     * (where contact handling keeps it). With {@code close}, also within 40 mm of one of them.
     *
     * @return the centre, or null when none was found
     */
    private static double[] placeable(Arena arena, World world, Engine engine, SplittableRandom random, boolean close) {
        for (int tries = 0; tries < 200; tries++) {
            double[] at = freeSpot(arena, world.field(), random, RobotTypes.KHEPERA1.body().radiusMm());
            double c = clearance(world, engine, at[0], at[1]);
            if (c >= RobotTypes.KHEPERA1.body().radiusMm() && (!close || c < RobotTypes.KHEPERA1.body().radiusMm() + 40)) {
                return at;
            }
        }
        return null;
    }
}
