package org.kheperasim.sim.engine.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.space.World;

/**
 * A measured robot's own tables, as the engine reads them: each sensor its own wall table, read at the
 * measured points; a lamp response in place of the modelled fall-off; and a robot file writes and reads
 * them all back unchanged.
 */
class MeasuredTablesTest {
    static final Settings QUIET = Settings.defaults().withNoise(0).with("prox.spikeRate", "0");
    private static final double[] ANGLES = {0, 20, 40};
    private static final double[] DISTANCES = {0, 10, 20, 30, 40, 60};

    /** Sensor i's own table: a falling shape, its level 0.6 + 0.1 i, its reach 4 i mm shorter. */
    static Response.Table table(int i) {
        double[][] v = new double[ANGLES.length][DISTANCES.length];
        for (int j = 0; j < ANGLES.length; j++) {
            for (int c = 0; c < DISTANCES.length; c++) {
                double d = DISTANCES[c] + (i % 3) * 4;
                v[j][c] = c == DISTANCES.length - 1 ? 0
                        : (0.6 + 0.1 * i) * (1 - 0.3 * j) * 1000 * StrictMath.exp(-StrictMath.pow(d / 22, 2));
            }
        }
        return new Response.Table(DISTANCES, ANGLES, v);
    }

    static RobotType measured(MeasuredTables tables) {
        return RobotTypes.KHEPERA1.calibrated("test", 53, 8, 0.08, table(3), 12, 0, 0,
                new RobotType.Measured("lab3", "2026-12-02", Collections.nCopies(8, 1.0), 1, 1, Double.NaN,
                        Double.NaN, tables));
    }

    static List<Response> perSensor() {
        List<Response> own = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            own.add(table(i));
        }
        return own;
    }

    @Test
    void eachSensorReadsItsOwnTableAtTheMeasuredPoints() {
        RobotType t = measured(MeasuredTables.NONE.withSensors(perSensor()));
        RobotType shared = measured(MeasuredTables.NONE);
        int differ = 0;
        for (double gap : new double[] {3, 8, 14, 22}) {
            for (double right : new double[] {0, 20, 75, 290}) {
                int[] sim = sample(t, wall(gap), gap, right);
                int[] one = sample(shared, wall(gap), gap, right);
                for (int i = 0; i < 8; i++) {
                    double want = WallReading.reading(t, table(i), i, 1, 12, gap, right);
                    assertEquals(want, sim[i], 1.0, "sensor " + i + " at " + gap + " mm, wall " + right + " deg right");
                    differ += sim[i] != one[i] ? 1 : 0;
                }
            }
        }
        assertTrue(differ > 30, "the sensors' own tables, not the shared one: " + differ + " readings differ");
    }

    @Test
    void aLampLightsTheSensorsAsItsMeasuredResponseSays() {
        LampResponse lamp = new LampResponse(new double[] {20, 100, 200, 400}, new double[] {1, 0.6, 0.2, 0.05});
        RobotType t = measured(MeasuredTables.NONE.withLamp(lamp));
        double face = 300 * OccupancyGrid.CELL_MM;
        String arena = String.format(Locale.ROOT, "khepera-arena 1\nname lamp\nsize 1219.2 1219.2\nrobot 500 600 0\n"
                + "light %s 600\nwall %s 100 %s 1100 8\n", 650, face + 300, face + 300);
        int[] light = run(t, arena, new Pose(500, 600, 0))[1];
        int[] modelled = run(RobotTypes.KHEPERA1, arena, new Pose(500, 600, 0))[1];
        for (int i = 2; i <= 3; i++) {
            RobotType.Sensor s = t.sensor(i);
            double lx = 150 - s.xMm();
            double ly = -s.yMm();
            double r = StrictMath.hypot(lx, ly);
            double facing = (lx * StrictMath.cos(StrictMath.toRadians(s.headingDeg()))
                    + ly * StrictMath.sin(StrictMath.toRadians(s.headingDeg()))) / r;
            double want = 480 - 460 * StrictMath.min(1, facing * lamp.activation(r));
            assertEquals(want, light[i], 1.0, "sensor " + i + " " + r + " mm from the lamp");
            assertNotEquals(modelled[i], light[i], "not the modelled fall-off");
        }
    }

    @Test
    void aRobotFileWritesItsMeasuredTablesAndReadsThemBack() {
        Response cap = table(1);
        RobotType t = measured(MeasuredTables.NONE.withSensors(perSensor()).withObjects(cap, table(6))
                .withNoise(List.of(1.0, 0.5, 2.0, 1.0, 1.0, 1.5, 1.0, 0.75))
                .withLamp(new LampResponse(new double[] {20, 100}, new double[] {0.9, 0.1})));
        String text = RobotFileWriter.write(t);
        assertTrue(text.contains("  sensor_tables:\n    - ["), text);
        RobotType back = RobotFileReader.parse("t.yaml", text);
        assertEquals(t.measured(), back.measured());
        assertEquals(text, RobotFileWriter.write(back), "saving again gives the same bytes");
    }

    @Test
    void aKindOfRobotReadsAsBefore() {
        // The beams' arithmetic of a robot without tables is the engine's of old: one response, times the
        // reflectance of what the beam met.
        double[] reflect = {0, 1, 0.9, 0.7, 0.8};
        Response r = RobotTypes.KHEPERA1.proximity().response();
        BeamResponse b = new BeamResponse(r, reflect, null, 8);
        for (int ray = 0; ray < 2 * r.anglesDeg().length - 1; ray++) {
            int j = (ray + 1) / 2;
            for (double d = 0; d < 60; d += 3.7) {
                assertEquals(r.weight(j) * reflect[BeamResponse.CAP] * r.along(j).valueAt(d),
                        b.value(5, ray, BeamResponse.CAP, d));
            }
        }
    }

    static String wall(double gap) {
        double face = 300 * OccupancyGrid.CELL_MM;
        return String.format(Locale.ROOT, "khepera-arena 1\nname wall\nsize 1219.2 1219.2\nrobot %s 600 0\n"
                + "wall %s 300 %s 900 8\n", face - 27.5 - gap, face + 4, face + 4);
    }

    /** @return the proximity readings with the wall {@code gap} mm from the body, {@code right} degrees right */
    static int[] sample(RobotType t, String arena, double gap, double right) {
        double face = 300 * OccupancyGrid.CELL_MM;
        return run(t, arena, new Pose(face - 27.5 - gap, 600, right))[0];
    }

    /** @return {proximity, light} after the first scans */
    static int[][] run(RobotType t, String arena, Pose at) {
        Engine engine = new Engine(new World(ArenaFormat.parse(arena, "t.arena")), 7);
        SimRobot robot = engine.addRobot("r", at, QUIET, t);
        for (int k = 0; k < 60; k++) {
            engine.step();
        }
        int[][] out = new int[2][8];
        for (int i = 0; i < 8; i++) {
            out[0][i] = robot.controls().visibleProximity(i);
            out[1][i] = robot.controls().visibleLight(i);
        }
        return out;
    }
}
