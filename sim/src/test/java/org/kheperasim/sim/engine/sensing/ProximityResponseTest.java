package org.kheperasim.sim.engine.sensing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.ProximityProfile;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.space.World;

/**
 * A white wall at 10, 20, 30 and 50 mm in front of the front sensors gives the reference response
 * (the default Khepera I profile) within the per-reading noise.
 */
class ProximityResponseTest {

    @ParameterizedTest(name = "wall at {0} mm")
    @ValueSource(ints = {10, 20, 30, 50})
    void frontSensorsFollowTheReferenceTable(int distanceMm) {
        // Put the wall's face exactly on a cell boundary, and the front sensors (25 mm ahead of the
        // robot's centre) exactly distanceMm from it.
        double cell = OccupancyGrid.CELL_MM;
        int faceCol = 300;
        double face = faceCol * cell;
        double robotX = face - 25 - distanceMm;
        String text = String.format(Locale.ROOT, "khepera-arena 1\nname wall\nsize 1219.2 1219.2\n"
                + "robot %s 600 0\nwall %s 400 %s 800 8\n", robotX, face + 4, face + 4);
        World world = new World(ArenaFormat.parse(text, "wall.arena"));
        Settings settings = Settings.defaults().with("noise.robot", "0").with("prox.spikeRate", "0");
        Engine engine = new Engine(world, 7);
        SimRobot robot = engine.addRobot("r", new Pose(robotX, 600, 0), settings);

        double expected = RobotTypes.KHEPERA1.proximity().response().along(0).valueAt(distanceMm) + settings.number("prox.offset");
        double sigma = settings.number("prox.noiseAbs") + settings.number("prox.noiseRel") * (expected - settings.number("prox.offset"));
        int samples = 0;
        double sum2 = 0;
        double sum3 = 0;
        int last = -1;
        for (int t = 0; t < 20_000; t++) {
            engine.step();
            int v2 = robot.controls().visibleProximity(2);
            int v3 = robot.controls().visibleProximity(3);
            assertTrue(StrictMath.abs(v2 - expected) <= 5 * sigma + 1,
                    "sensor 2 read " + v2 + ", expected " + expected + " +/- " + 5 * sigma);
            assertTrue(StrictMath.abs(v3 - expected) <= 5 * sigma + 1,
                    "sensor 3 read " + v3 + ", expected " + expected + " +/- " + 5 * sigma);
            int cycle = (int) (engine.timeNanos() / robot.link().pollCycleNanos());
            if (cycle != last) {
                last = cycle;
                samples++;
                sum2 += v2;
                sum3 += v3;
            }
        }
        double tolerance = 4 * sigma / StrictMath.sqrt(samples) + 1;
        assertEquals(expected, sum2 / samples, tolerance, "mean of sensor 2 over " + samples + " readings");
        assertEquals(expected, sum3 / samples, tolerance, "mean of sensor 3 over " + samples + " readings");
    }

    /**
     * The khepera2 profile gives the published white-sheet readings (RoadNarrows' default Khepera II
     * calibration, Khepera manual section 3.1.8) as whole readings, the sensor's offset included:
     * 1000 at 10 mm, 450 at 20 mm, ... 80 at 100 mm, not 15 counts above them.
     */
    @ParameterizedTest(name = "white sheet at {0} mm reads {1}")
    @org.junit.jupiter.params.provider.CsvSource({"10,1000", "20,450", "30,275", "40,190", "50,150", "60,125",
        "70,110", "80,100", "90,90", "100,80"})
    void khepera2ReadsThePublishedTable(int distanceMm, int published) {
        Settings settings = Settings.defaults().withNoise(0).with("prox.spikeRate", "0").with("prox.profile", "khepera2");
        Engine engine = new Engine(wallAhead(distanceMm), 7);
        double face = 300 * OccupancyGrid.CELL_MM;
        SimRobot robot = engine.addRobot("r", new Pose(face - 25 - distanceMm, 600, 0), settings);
        for (int t = 0; t < 100; t++) {
            engine.step();
        }
        for (int sensor : new int[] {2, 3}) {
            int v = robot.controls().visibleProximity(sensor);
            assertTrue(StrictMath.abs(v - published) <= 1,
                    "sensor " + sensor + " at " + distanceMm + " mm read " + v + ", published " + published);
        }
    }

    private static World wallAhead(int distanceMm) {
        double face = 300 * OccupancyGrid.CELL_MM;
        double robotX = face - 25 - distanceMm;
        return new World(ArenaFormat.parse(String.format(Locale.ROOT, "khepera-arena 1\nname wall\nsize 1219.2 1219.2\n"
                + "robot %s 600 0\nwall %s 400 %s 800 8\n", robotX, face + 4, face + 4), "wall.arena"));
    }

    @org.junit.jupiter.api.Test
    void aProfileReachesOneMillimetreAtLeast() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new ProximityProfile("tiny", new double[] {0, 0.4}, new double[] {1023, 0}));
        assertTrue(e.getMessage().contains("at least 1.0 mm"), e.getMessage());
        assertEquals(1.0, new ProximityProfile("short", new double[] {0, 1}, new double[] {1023, 0}).rangeMm());
    }
}
