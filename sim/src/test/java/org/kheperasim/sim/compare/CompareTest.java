package org.kheperasim.sim.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.testfixtures.Cli;

/**
 * {@code khepera-sim compare} on recordings with known answers: a simulated run standing in for the
 * real one (written in robot-link's recording format, in process: not yet over {@code serve}) gives
 * zero divergence against the same simulation; a recording with one sensor raised by 100 gives RMS
 * 100 on that sensor alone; one whose wheels stall at 2 s parts when the simulated robot has moved
 * the threshold away from where it stalled.
 */
class CompareTest {
    private static final long SEED = 5;

    private static Track simulated(double seconds) {
        return SimulatedRun.run(ArenaFormat.resolve("lab"), null, null, "WallFollower", Settings.defaults(), SEED, seconds, 10);
    }

    private static Cli.Printed compare(Path recording, Path out) {
        return Cli.main("compare", recording.toString(), "--arena", "lab", "--controller", "WallFollower", "--seed",
                String.valueOf(SEED), "--out", out.toString());
    }

    @Test
    void theSameSimulationDoesNotDiverge(@TempDir Path dir) throws Exception {
        Path rec = dir.resolve("same.rec");
        simulated(4).write(rec, "the simulator standing in for a robot");
        Cli.Printed p = compare(rec, dir);
        assertEquals(0, p.code(), p.err());
        assertTrue(p.out().contains("counts: 0.0 0.0 0.0 0.0 0.0 0.0 0.0 0.0"), p.out());
        assertTrue(p.out().contains("never more than 30.0 mm"), p.out());
        assertTrue(Files.readString(dir.resolve("same-compare.json")).contains("\"partedAt\":null"));
        assertTrue(Files.size(dir.resolve("same-compare.png")) > 1000);
    }

    @Test
    void oneSensorRaisedBy100ShowsAsRms100OnItAlone(@TempDir Path dir) throws Exception {
        List<Track.Point> points = new ArrayList<>();
        for (Track.Point q : simulated(3).samples()) {
            int[] prox = q.proximity().clone();
            prox[2] += 100;
            points.add(new Track.Point(q.seconds(), prox, q.left(), q.right()));
        }
        Path rec = dir.resolve("bright.rec");
        new Track(points).write(rec, "sensor 2 reads 100 more");
        Cli.Printed p = compare(rec, dir);
        assertEquals(0, p.code(), p.err());
        assertTrue(p.out().contains("counts: 0.0 0.0 100.0 0.0 0.0 0.0 0.0 0.0"), p.out());
    }

    @Test
    void aStallPartsWhenTheSimulatedRobotIsTheThresholdAway(@TempDir Path dir) throws Exception {
        double stall = 2.0;
        List<Track.Point> points = new ArrayList<>();
        Track.Point stalled = null;
        for (Track.Point q : simulated(6).samples()) {
            if (q.seconds() >= stall && stalled == null) {
                stalled = q;
            }
            Track.Point c = stalled == null ? q : stalled;
            points.add(new Track.Point(q.seconds(), q.proximity(), c.left(), c.right()));
        }
        Path rec = dir.resolve("stall.rec");
        new Track(points).write(rec, "the wheels stall at 2 s");
        // The known answer, from the simulator's own positions: when the robot is 30 mm from where it was at 2 s.
        List<double[]> xy = new ArrayList<>();
        Simulation.builder().arena(ArenaFormat.resolve("lab")).controller("WallFollower").seed(SEED).seconds(6)
                .listener(s -> {
                    RobotView r = s.robots().get(0);
                    xy.add(new double[] {s.timeNanos() / 1e9, r.x(), r.y()});
                }, 10).run();
        double[] at = xy.stream().filter(v -> v[0] >= stall - 1e-9).findFirst().orElseThrow();
        double expected = xy.stream().filter(v -> v[0] >= stall && StrictMath.hypot(v[1] - at[1], v[2] - at[2]) > 30).mapToDouble(v -> v[0])
                .findFirst().orElseThrow();
        Cli.Printed p = compare(rec, dir);
        assertEquals(0, p.code(), p.err());
        String json = Files.readString(dir.resolve("stall-compare.json"));
        double parted = Double.parseDouble(json.replaceAll("(?s).*\"partedAt\":([0-9.]+).*", "$1"));
        assertEquals(expected, parted, 0.1, p.out());
    }

    @Test
    void aFileThatIsNoRecordingIsOneLine(@TempDir Path dir) throws Exception {
        Path bad = dir.resolve("bad.rec");
        Files.writeString(bad, "hello\n");
        Cli.Printed p = compare(bad, dir);
        assertEquals(2, p.code());
        assertTrue(p.err().contains("bad.rec") && p.err().strip().lines().count() == 1, p.err());
    }
}
