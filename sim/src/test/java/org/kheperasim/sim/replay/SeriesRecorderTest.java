package org.kheperasim.sim.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.run.Simulation;

/**
 * The live plot's samples are kept at their simulated period whatever the speed (the old plot sampled
 * the screen and was empty at full speed), and they are the trace's values.
 */
class SeriesRecorderTest {
    @TempDir
    Path dir;

    @Test
    void everySampleOfARunAtFullSpeedIsKeptAsTheTraceHasIt() throws Exception {
        SeriesRecorder rec = new SeriesRecorder();
        Path trace = dir.resolve("run.trace");
        Simulation.builder().arena("lab").controller("Braitenberg").seed(3).seconds(30).listener(rec, 100)
                .trace(trace).sampleMillis(100).run();
        RobotSeries s = rec.series(0);
        assertEquals(0.0, s.time(0), 1e-9);
        assertEquals(300, s.size(), "0 to 29.9 s every 100 ms (the trace also has the last instant, 30 s)");
        assertNull(rec.series(1), "the lab has one robot");
        RobotSeries fromTrace = ReplayFiles.open(trace).series(0);
        assertEquals(fromTrace.size() - 1, s.size());
        for (int k = 0; k < s.size(); k += 37) {
            assertEquals(fromTrace.time(k), s.time(k), 1e-9);
            for (int c = 0; c < RobotSeries.CHANNELS; c++) {
                assertEquals(fromTrace.value(c, k), s.value(c, k), RobotSeries.channelName(c) + " at " + s.time(k));
            }
        }
        double[][] span = s.extract(10, 20, new int[] {RobotSeries.PROXIMITY + 2, RobotSeries.SPEED}, 0);
        assertEquals(101, span[0].length, "10 s to 20 s inclusive");
        assertEquals(10.0, span[0][0], 1e-9);
        double[][] thin = s.extract(0, 30, new int[] {RobotSeries.LIGHT}, 50);
        assertEquals(true, thin[0].length <= 50, "thinned for drawing: " + thin[0].length);
    }
}
