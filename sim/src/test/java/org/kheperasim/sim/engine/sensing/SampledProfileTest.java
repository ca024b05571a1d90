package org.kheperasim.sim.engine.sensing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.robot.SampleFit;
import org.kheperasim.sim.engine.robot.SampleResponses;
import org.kheperasim.sim.engine.robot.WallReading;
import org.kheperasim.sim.engine.space.World;

/**
 * {@code prox.profile=sample:PATH}: the engine reads a sampled table's fitted response, as
 * {@link WallReading} predicts it for a straight wall, at any heading. Uses a small synthetic sample
 * file (a made-up falling response), not the Nolfi data.
 */
class SampledProfileTest {

    /** A made-up sampled wall: 8 sensors, 36 headings, 12 blocks from 2 mm in 3 mm steps. */
    static String syntheticTable() {
        StringBuilder sb = new StringBuilder("8 36 12 2 3\n");
        for (int t = 0; t < 12; t++) {
            sb.append("TURN ").append(t).append('\n');
            for (int k = 0; k < 36; k++) {
                double gap = 2 + 3 * t;
                for (int i = 0; i < 8; i++) {
                    double d = WallReading.beamDistanceMm(RobotTypes.KHEPERA1, i, gap, k * 10, 0);
                    double off = StrictMath.abs(Math.IEEEremainder(-k * 10 - RobotTypes.KHEPERA1.sensor(i).headingDeg(), 360));
                    double v = d > 40 || off > 60 ? 0 : (1 - d / 40) * (1 - d / 40) * StrictMath.cos(StrictMath.toRadians(off * 1.4));
                    int counts = (int) StrictMath.rint(StrictMath.max(0, StrictMath.min(1, v)) * 1023);
                    sb.append(String.format(Locale.ROOT, "%.6f ", counts / 1023.0));
                }
                sb.append('\n');
            }
        }
        return sb.append("END\n").toString();
    }

    @Test
    void theEngineReadsTheFittedTableAtAnyHeading(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("synthetic-wall.sample");
        Files.writeString(file, syntheticTable());
        Settings settings = Settings.defaults().withNoise(0).with("prox.spikeRate", "0").with("prox.offset", "0")
                .with("prox.profile", "sample:" + file);
        SampleFit.Result fit = SampleResponses.fit(file.toString(), RobotTypes.KHEPERA1);
        double face = 300 * OccupancyGrid.CELL_MM;
        int checked = 0;
        for (double gap : new double[] {6.5, 12, 17.5}) {
            for (double right : new double[] {0, 25, 70}) {
                double x = face - 27.5 - gap;
                World world = new World(ArenaFormat.parse(String.format(Locale.ROOT, "khepera-arena 1\nname wall\n"
                        + "size 1219.2 1219.2\nrobot %s 600 0\nwall %s 300 %s 900 8\n", x, face + 4, face + 4), "wall.arena"));
                Engine engine = new Engine(world, 7);
                SimRobot robot = engine.addRobot("r", new Pose(x, 600, right), settings);
                for (int t = 0; t < 100; t++) {
                    engine.step();
                }
                for (int i = 0; i < 8; i++) {
                    double expected = WallReading.reading(RobotTypes.KHEPERA1, fit.table(), i, 1, 0, gap, right);
                    int v = robot.controls().visibleProximity(i);
                    assertEquals(expected, v, 1.5, "sensor " + i + ", wall " + gap + " mm, " + right + " degrees right");
                    if (v > 100) {
                        checked++;
                    }
                }
            }
        }
        assertTrue(checked >= 10, "only " + checked + " readings lit");
    }

    @Test
    void aMissingSampleFileIsOneLineNamingIt() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Settings.defaults().with("prox.profile", "sample:/no/such/wall.sample"));
        assertTrue(e.getMessage().contains("/no/such/wall.sample") && !e.getMessage().contains("\n"), e.getMessage());
    }
}
