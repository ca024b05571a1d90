package org.kheperasim.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.testing.KheperaAssertions.LAMP;
import static org.kheperasim.testing.KheperaAssertions.ROBOT;
import static org.kheperasim.testing.KheperaAssertions.assertThat;
import static org.kheperasim.testing.KheperaAssertions.seconds;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Wall;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.run.ControllerCatalog;
import org.kheperasim.sim.run.RunRecording;
import org.kheperasim.sim.run.RunSession;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.trace.LineFileWriter;
import org.opentest4j.AssertionFailedError;

/**
 * A recorded run (a trace file, or a run recording folder the window saves) reads into the shape of a run
 * made by a test, less what a trace does not record; made again, it is identical, and a recording that no
 * longer matches its controller or settings is caught at its first differing sample.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RecordedRunTest {

    @Test
    void aSavedTraceReadsBackAsTheRunThatWroteIt(@TempDir Path dir) {
        Run live = Run.of(student.Straight.class).in(Fixtures.resource("head-on.arena")).seconds(20).seed(5).run();
        Path trace = live.saveTo(dir);
        assertEquals(dir.resolve("head-on-Straight-seed5.trace"), trace);
        assertTrue(Files.isRegularFile(dir.resolve("head-on.arena")), "the arena lies beside the trace");

        Run recorded = Run.load(trace);
        assertEquals(trace, recorded.recordedFrom().orElseThrow());
        assertEquals(live.trace(), recorded.trace());
        assertEquals(live.seed(), recorded.seed());
        assertEquals(live.duration(), recorded.duration());
        assertEquals(live.caps(), recorded.caps());
        for (int i = 0; i < live.robots().size(); i++) {
            RobotRun a = live.robot(i);
            RobotRun b = recorded.robot(i);
            assertEquals(a.name(), b.name());
            assertEquals(a.path(), b.path());
            // Live contacts are the engine's events, at their ticks; a trace has only its samples: each contact a
            // sample saw is recorded from the first sample at or after its tick, to the last sample before its end.
            List<Contact> seen = a.contacts().stream().filter(c -> !c.betweenSamples()).toList();
            assertEquals(seen.size(), b.contacts().size(), "robot " + i + ": " + seen + " / " + b.contacts());
            for (int k = 0; k < seen.size(); k++) {
                Contact exact = seen.get(k);
                Contact sampled = b.contacts().get(k);
                assertEquals(exact.what(), sampled.what(), exact + " / " + sampled);
                assertFalse(sampled.from().isBefore(exact.from()), exact + " / " + sampled);
                assertTrue(sampled.from().nanos() - exact.from().nanos() < 50_000_000L, exact + " / " + sampled);
                assertFalse(sampled.to().isAfter(exact.to()), exact + " / " + sampled);
                assertTrue(exact.to().nanos() - sampled.to().nanos() < 50_000_000L, exact + " / " + sampled);
            }
            assertEquals(a.regionsEntered().keySet(), b.regionsEntered().keySet());
            a.regionsEntered().forEach((name, t) ->
                    assertEquals(t.seconds(), b.regionsEntered().get(name).seconds(), 0.05, "a sample within 50 ms"));
            assertEquals(Ending.Kind.NOT_RECORDED, b.ending().kind());
            assertEquals(-1, b.collisions());
        }
        AssertionFailedError unknown = assertThrows(AssertionFailedError.class, () -> assertThat(recorded).endedNormally());
        assertTrue(unknown.getMessage().startsWith("A trace does not say how Straight#0's controller ended."), unknown.getMessage());
        assertTrue(unknown.getMessage().contains("  trace:    " + trace), unknown.getMessage());

        Rerun again = recorded.rerun();
        assertTrue(again.identical(), again.toString());
        assertEquals(again.again().robot(3).ending(), live.robot(3).ending());
        assertThat(recorded).replaysIdentically().entered("middle").before(seconds(7));
    }

    @Test
    void aTraceOfTheRunCommandFindsItsBundledArena(@TempDir Path dir) {
        Path trace = dir.resolve("follow.trace");
        Simulation.builder().arena("maze-easy").controller("WallFollower").seed(4).seconds(60).trace(trace).console(l -> { })
                .run();
        Run recorded = Run.load(trace);
        assertEquals("maze-easy", recorded.arena());
        assertEquals("org.kheperasim.controllers.WallFollower", recorded.robot().controller());
        assertThat(recorded).neverTouched(LAMP, ROBOT).entered("c0_0").before(seconds(1));
        assertTrue(recorded.score().task("visit c*").points() > 0, recorded.score().toString());
        assertTrue(recorded.rerun().identical());
    }

    @Test
    void aChangedTraceIsCaughtAtItsFirstDifferingSample(@TempDir Path dir) throws Exception {
        Path trace = Run.of("Braitenberg").in("lab").seconds(10).seed(2).run().saveTo(dir);
        List<String> lines = new ArrayList<>(Files.readAllLines(trace));
        int k = lines.indexOf(lines.stream().filter(l -> l.startsWith("5.000 0 ")).findFirst().orElseThrow());
        String[] f = lines.get(k).split(" ");
        f[2] = String.format(java.util.Locale.ROOT, "%.3f", Double.parseDouble(f[2]) + 1);
        lines.set(k, String.join(" ", f));
        Files.write(trace, lines);

        Rerun again = Run.load(trace).rerun();
        assertFalse(again.identical());
        assertTrue(again.firstDifference().orElseThrow().startsWith("sample line 101 (t = 5.000 s, robot 0): x_mm recorded "),
                again.toString());
        AssertionFailedError e = assertThrows(AssertionFailedError.class, () -> assertThat(Run.load(trace)).replaysIdentically());
        assertTrue(e.getMessage().startsWith("The run came out differently when made again.\n"), e.getMessage());
        assertTrue(e.getMessage().contains("first difference at sample line 101 (t = 5.000 s, robot 0)"), e.getMessage());
    }

    @Test
    void aWindowRecordingWithAnArenaEditReadsAndReplays(@TempDir Path dir) throws Exception {
        Path rec = Files.createDirectories(dir.resolve("recording"));
        Arena lab = ArenaFormat.loadBundled("lab");
        Settings settings = Settings.defaults().with("noise.robot", "0");
        RunSession s = new RunSession(lab, "org.kheperasim.controllers.Braitenberg", new ControllerCatalog(List.of()), 8,
                settings, line -> { }, HostOptions.defaults());
        s.trace(LineFileWriter.open(rec.resolve("run.trace")), 50);
        s.runTo(5_000_000_000L);
        // An instructor drops a wall across the lab's middle, in front of the robot, at 5 s.
        List<Wall> walls = new ArrayList<>(lab.walls());
        walls.add(new Wall(100, 800, 1100, 800, 8));
        s.edit(new Arena(lab.name(), lab.width(), lab.height(), lab.robots(), walls, lab.lights(), lab.caps(), lab.regions(),
                lab.assignment()));
        s.runTo(20_000_000_000L);
        s.close();
        RunRecording.save(s, 20, List.of(), settings, rec);

        Run recorded = Run.load(rec);
        assertEquals("noise.robot=0", recorded.settings());
        assertEquals(rec.resolve("run.trace"), recorded.recordedFrom().orElseThrow());
        assertTrue(recorded.rerun().identical(), "the edit is made again at its time");
        // The trace alone, without the recording's edit, is another run: the edit mattered, and was made again.
        Path alone = Files.createDirectories(dir.resolve("alone"));
        Files.copy(rec.resolve("run.trace"), alone.resolve("lab.trace"));
        Rerun withoutEdit = Run.load(alone.resolve("lab.trace")).rerun();
        assertFalse(withoutEdit.identical(), withoutEdit.toString());
        assertTrue(withoutEdit.firstDifference().orElseThrow().contains("(t = 5."), withoutEdit.toString());
    }

    @Test
    void aTraceWhoseArenaCannotBeFoundSaysHowToGiveIt(@TempDir Path dir) throws Exception {
        Path trace = Run.of(student.Straight.class).in(Fixtures.resource("head-on.arena")).seconds(1).run().saveTo(dir);
        Files.delete(dir.resolve("head-on.arena"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Run.load(trace));
        assertTrue(e.getMessage().contains("give it: Run.load(trace, Path.of(\"head-on.arena\"))"), e.getMessage());
        assertEquals(4, Run.load(trace, Fixtures.resource("head-on.arena")).robots().size());
    }
}
