package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Wall;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.host.HostOptions;

/**
 * A run driven in chunks, paced against the wall clock, with arena edits in the middle, computes
 * exactly what a headless run computes, and a headless run replaying the recorded edits gives the
 * same trace byte for byte.
 */
class RunSessionTest {
    private static final long SEED = 7;
    private static final long END = 8_000_000_000L;

    private static Arena lab() {
        return ArenaFormat.loadBundled("lab");
    }

    /** The lab with a wall across the robot's way ahead (it starts at (609.6, 609.6) facing up). */
    private static Arena withWallAhead(Arena a) {
        List<Wall> walls = new ArrayList<>(a.walls());
        walls.add(new Wall(500, 760, 720, 760, 8));
        return new Arena(a.name(), a.width(), a.height(), a.robots(), walls, a.lights(), a.caps(), a.regions());
    }

    private static String headless(EditLog edits) {
        StringWriter out = new StringWriter();
        Simulation.builder().arena(lab()).controller("Braitenberg").seed(SEED).seconds(END / 1e9).trace(out)
                .edits(edits).run();
        return out.toString();
    }

    private static RunSession session(StringWriter out) {
        RunSession s = new RunSession(lab(), "Braitenberg", new ControllerCatalog(List.of()), SEED, Settings.defaults(),
                line -> { }, HostOptions.defaults());
        s.trace(out, 50);
        return s;
    }

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void chunkedRunGivesTheSameTraceAsOneCall() {
        StringWriter out = new StringWriter();
        try (RunSession s = session(out)) {
            long t = 0;
            long[] chunks = {1_000_000, 3_000_000, 7_000_000, 10_000_000, 100_000_000};
            for (int k = 0; t < END; k++) {
                t = StrictMath.min(END, t + chunks[k % chunks.length]);
                s.runTo(t);
            }
        }
        assertEquals(headless(new EditLog()), out.toString());
    }

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void pacedRunWithAnEditReplaysExactlyHeadless() throws Exception {
        StringWriter out = new StringWriter();
        RunSession s = session(out);
        PacedRunner runner = new PacedRunner(s, null);
        runner.setSpeed(4);
        runner.pauseAt(END);
        runner.start();
        // Drop a wall in front of the robot while it runs, at whatever simulated time the wall clock gives.
        while (runner.latest().timeNanos() < 1_500_000_000L) {
            Thread.sleep(5);
        }
        runner.edit(withWallAhead(lab()));
        runner.setSpeed(PacedRunner.MAX_SPEED);
        while (runner.state() == PacedRunner.State.RUNNING) {
            Thread.sleep(5);
        }
        assertEquals(END, runner.latest().timeNanos(), "the run pauses at the asked end");
        EditLog recorded = EditLog.parse(s.edits().write(), "recorded");
        assertTrue(runner.stopAndWait(10_000));
        assertEquals(1, recorded.size());
        long at = recorded.edits().get(0).timeNanos();
        assertTrue(at >= 1_500_000_000L && at < END, "the edit is stamped with the simulated time it took effect: " + at);
        String replay = headless(recorded);
        assertEquals(replay, out.toString(), "replaying the recorded edit headless gives the same trace, byte for byte");
        assertNotEquals(headless(new EditLog()), out.toString(), "the wall changed the run");
    }

    /**
     * The window's run ends where {@code run} ends it: at the end set (the arena's time limit), the
     * controllers stopped and the trace finished there, the very trace a headless run of that length
     * writes; a publish listener is told of the settled end, and a step cannot pass it.
     */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aPacedRunEndsAtItsEndAsAHeadlessRunOfThatLength() throws Exception {
        StringWriter out = new StringWriter();
        RunSession s = session(out);
        PacedRunner runner = new PacedRunner(s, null);
        List<Long> settled = new java.util.concurrent.CopyOnWriteArrayList<>();
        runner.addPublishListener((session, done) -> {
            if (done) {
                settled.add(session.timeNanos());
            }
        });
        runner.endAt(END);
        runner.pauseAt(END - 5_000_000L);
        runner.setSpeed(PacedRunner.MAX_SPEED);
        runner.start();
        while (runner.state() != PacedRunner.State.PAUSED || runner.latest().timeNanos() != END - 5_000_000L) {
            Thread.sleep(5);
        }
        runner.step();
        while (runner.state() != PacedRunner.State.TIME_UP) {
            Thread.sleep(5);
        }
        assertEquals(END, runner.latest().timeNanos(), "a 10 ms step from 5 ms before the end stops at the end");
        assertTrue(runner.stopAndWait(10_000));
        assertEquals(PacedRunner.State.TIME_UP, runner.state(), "stopping an ended run leaves it ended at its time");
        assertEquals(headless(new EditLog()), out.toString(), "the trace is the headless run's of that length");
        assertEquals(END, settled.get(settled.size() - 1), "the end was published as settled");
    }

    @Test
    void editLogRoundTripsAsText() {
        EditLog log = new EditLog();
        log.add(1_000_000, withWallAhead(lab()));
        log.add(2_000_000, lab());
        EditLog back = EditLog.parse(log.write(), "x");
        assertEquals(log.edits(), back.edits());
    }
}
