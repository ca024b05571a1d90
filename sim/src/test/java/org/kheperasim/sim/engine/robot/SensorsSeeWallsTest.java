package org.kheperasim.sim.engine.robot;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.space.World;

/** For each robot, a wall placed in front of each sensor in turn raises that sensor above its open-floor value. */
class SensorsSeeWallsTest {
    private static final Settings QUIET = Settings.defaults().withNoise(0);

    @ParameterizedTest
    @ValueSource(strings = {"khepera1", "khepera2", "epuck"})
    void aWallInFrontOfEachSensorRaisesIt(String name) {
        RobotType type = RobotTypes.named(name);
        int[] open = read(type, null);
        for (int i = 0; i < type.sensorCount(); i++) {
            int[] near = read(type, type.sensor(i));
            assertTrue(near[i] > open[i], name + " sensor " + i + " (" + type.sensor(i).name() + ") read " + near[i]
                    + " with a wall 10 mm ahead of it, " + open[i] + " on the open floor");
        }
    }

    /** The readings of a robot at the arena's centre heading 0, with a wall 10 mm in front of {@code facing} (or none). */
    private static int[] read(RobotType type, RobotType.Sensor facing) {
        double cx = 600;
        double cy = 600;
        StringBuilder text = new StringBuilder("khepera-arena 1\nname probe\nsize 1200 1200\nrobot 600 600 0\n");
        if (facing != null) {
            double h = StrictMath.toRadians(facing.headingDeg());
            double sx = cx + facing.xMm();
            double sy = cy + facing.yMm();
            double d = 10 + 4; // the wall's face 10 mm from the sensor, its centre line half its thickness beyond
            double wx = sx + d * StrictMath.cos(h);
            double wy = sy + d * StrictMath.sin(h);
            double px = -StrictMath.sin(h) * 30;
            double py = StrictMath.cos(h) * 30;
            text.append(String.format(Locale.ROOT, "wall %.3f %.3f %.3f %.3f 8\n", wx - px, wy - py, wx + px, wy + py));
        }
        World world = new World(ArenaFormat.parse(text.toString(), "probe.arena"));
        Engine engine = new Engine(world, 1);
        SimRobot robot = engine.addRobot("r", new Pose(cx, cy, 0), QUIET, type);
        for (int t = 0; t < 200; t++) {
            engine.step();
        }
        int[] out = new int[type.sensorCount()];
        robot.onBoard().readProximity(out);
        return out;
    }
}
