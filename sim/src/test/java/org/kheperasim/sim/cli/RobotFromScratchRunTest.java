package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.testfixtures.Cli;

/**
 * A robot file made from scratch, not bundled ({@code src/test/resources/robots/roundbot.yaml}:
 * radius 40 mm, wheel base 64 mm, 6 mm/s speed units, its own sensor ring, a table response), runs
 * the bundled Braitenberg headless with {@code run --robot-file}: the trace names its type, it
 * cruises at the Braitenberg's 48 mm/s in its own speed units (8 of its 6 mm/s units, where a Khepera
 * sets 6 of 8 mm/s), and it travels.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RobotFromScratchRunTest {
    @TempDir
    Path dir;

    @Test
    void aRobotFileFromScratchRunsHeadless() throws Exception {
        Path trace = dir.resolve("run.trace");
        Cli.Printed p = Cli.main("run", "--arena", "lab", "--robot-file", "src/test/resources/robots/roundbot.yaml",
                "--controller", "Braitenberg", "--seconds", "30", "--seed", "4", "--trace", trace.toString());
        assertEquals(0, p.code(), p.out() + p.err());
        List<String> lines = Files.readAllLines(trace);
        assertTrue(lines.contains("# robot-types 0=roundbot"), String.join("\n", lines.subList(0, 12)));
        double travelled = 0;
        double[] last = null;
        double lastT = 0;
        double cruise = Double.NaN;
        for (String l : lines) {
            if (l.startsWith("#")) {
                continue;
            }
            String[] f = l.split(" ");
            double[] xy = {Double.parseDouble(f[2]), Double.parseDouble(f[3])};
            if (last != null) {
                double step = StrictMath.hypot(xy[0] - last[0], xy[1] - last[1]);
                travelled += step;
                double t = Double.parseDouble(f[0]);
                if (Double.isNaN(cruise) && f[5].equals("8") && f[6].equals("8") && t >= 0.5) {
                    cruise = step / (t - lastT);
                }
            }
            last = xy;
            lastT = Double.parseDouble(f[0]);
        }
        assertEquals(48, cruise, 2, "8 speed units of 6 mm/s, mm/s");
        assertTrue(travelled > 500, "it travelled " + travelled + " mm in 30 s");
    }
}
