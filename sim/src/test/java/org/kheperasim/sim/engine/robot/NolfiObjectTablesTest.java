package org.kheperasim.sim.engine.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.Pose;

/**
 * The Nolfi lab's cylinder and light tables (GPL data, read in place from {@code ../shared/real-khepera/},
 * never copied) pointed at by a measured robot file: a cap then reads as the real robot read the cylinder,
 * far less than the wall at the same gap, where the kind's model (the wall's table times the cap's
 * reflectance, 1) reads it as the wall; and the light sensors follow the light table.
 */
class NolfiObjectTablesTest {
    @TempDir
    Path dir;

    /**
     * A Khepera whose measured part points at the cylinder and light files; its wall response is a table on
     * the fit's beam angles (0 to 80 degrees by 10, the angles the cylinder tables were fitted at), so that
     * the cap's beams are cast where the fit cast them.
     */
    private Path robotFile() throws Exception {
        String k = RobotTypes.bundledText("khepera1");
        int from = k.indexOf("  response: curve");
        int to = k.indexOf("  offset:");
        StringBuilder rows = new StringBuilder();
        for (int j = 0; j < 9; j++) {
            rows.append("    - [").append(1000 - 100 * j).append(", 0]\n");
        }
        String text = k.substring(0, from).replace("name: khepera1", "name: nolfi") + "  response: table\n"
                + "  angles: [0, 10, 20, 30, 40, 50, 60, 70, 80]\n  distances: [0, 60]\n  values:\n" + rows
                + k.substring(to)
                + "measured:\n  robot: nolfi\n  date: 2022-05-17\n  gains: [1, 1, 1, 1, 1, 1, 1, 1]\n"
                + "  wheel_calibration: [1, 1]\n"
                + "  cap_sample: " + NolfiWallTableTest.sampleFile("khepera-cylinder.sample") + "\n"
                + "  lamp_sample: " + NolfiWallTableTest.sampleFile("khepera-light.sample") + "\n";
        Path file = dir.resolve("nolfi.yaml");
        Files.writeString(file, text);
        return file;
    }

    @Test
    void aCapReadsAsTheRealRobotReadTheCylinder() throws Exception {
        SampleTable cyl = SampleTable.read(NolfiWallTableTest.sampleFile("khepera-cylinder.sample"));
        SampleTable wall = SampleTable.read(NolfiWallTableTest.sampleFile("khepera-wall.sample"));
        RobotType measured = RobotTypes.load(robotFile());
        double errMeasured = 0;
        double errWall = 0;
        int n = 0;
        StringBuilder log = new StringBuilder();
        for (int t = 3; t <= 9; t++) {
            double gap = cyl.gapMm(t);
            double data = (cyl.counts(t, 0, 2) + cyl.counts(t, 0, 3)) / 2.0;
            // The kind's model reads a cap as the wall times prox.reflect.cap (1): at best, as the real wall read.
            double asWall = (wall.counts(t, 0, 2) + wall.counts(t, 0, 3)) / 2.0;
            double withTable = front(measured, gap);
            log.append(String.format(Locale.ROOT, "gap %.0f mm: the cylinder %.0f, the wall %.0f, the cap with the"
                    + " cylinder tables %.0f%n", gap, data, asWall, withTable));
            errMeasured += StrictMath.abs(withTable - data);
            errWall += StrictMath.abs(asWall - data);
            n++;
        }
        System.out.print(log);
        assertTrue(errMeasured / n <= 0.05 * 1023, "mean error with the cylinder tables " + errMeasured / n + "\n" + log);
        assertTrue(errWall / n > 4 * errMeasured / n, "read as the wall: mean error " + errWall / n + "\n" + log);
    }

    @Test
    void theLightSensorsFollowTheLightTable() throws Exception {
        RobotType measured = RobotTypes.load(robotFile());
        LampResponse lamp = measured.measured().tables().lamp();
        SampleTable light = SampleTable.read(NolfiWallTableTest.sampleFile("khepera-light.sample"));
        assertEquals(light.blocks(), lamp.distancesMm().length);
        // A lamp 105 mm ahead of the body (block 5 of the light table): the front pair reads it as that block says.
        double face = 300 * OccupancyGrid.CELL_MM;
        double x = 500;
        String arena = String.format(Locale.ROOT, "khepera-arena 1\nname lamp\nsize 1219.2 1219.2\nrobot %s 600 0\n"
                + "light %s 600 range 1000\nwall %s 100 %s 1100 8\n", x, x + 27.5 + light.gapMm(5), face + 300,
                face + 300);
        int[] read = MeasuredTablesTest.run(measured, arena, new Pose(x, 600, 0))[1];
        int best = 0;
        for (int k = 0; k < light.angles(); k++) {
            for (int i = 0; i < 8; i++) {
                best = StrictMath.max(best, light.counts(5, k, i));
            }
        }
        double want = SampleTable.ambientReading(best, 480, 20);
        assertEquals(want, (read[2] + read[3]) / 2.0, 0.05 * 460, "block 5 of the light table, "
                + best + " of 1023 lit");
    }

    /** @return the front pair's mean reading with a cap straight ahead, {@code gap} mm from the body */
    private static double front(RobotType t, double gap) {
        double x = 500;
        String arena = String.format(Locale.ROOT, "khepera-arena 1\nname cap\nsize 1219.2 1219.2\nrobot %s 600 0\n"
                + "cap %s 600\n", x, x + 27.5 + gap + Cap.DEFAULT_RADIUS);
        int[] p = MeasuredTablesTest.run(t, arena, new Pose(x, 600, 0))[0];
        return (p[2] + p[3]) / 2.0;
    }
}
