package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.cli.Main;
import org.kheperasim.sim.edit.ArenaEdits;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.run.ControllerCatalog;
import org.kheperasim.sim.run.PacedRunner;
import org.kheperasim.sim.run.RunSession;

/**
 * The window's "Save run recording": a paced run with settings and an edit made while it ran is
 * replayed by the command in replay.txt, and the replay's trace equals the run's trace.
 */
class RunRecordingTest {

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theSavedRecordingReplaysTheRunByteForByte(@TempDir Path dir) throws Exception {
        Arena lab = ArenaFormat.loadBundled("lab");
        Settings settings = Settings.defaults().with("motor.left.calibration", "0.9").with("prox.2.dead", "true");
        StringWriter trace = new StringWriter();
        RunSession session = new RunSession(lab, "Braitenberg", new ControllerCatalog(List.of()), 11, settings, l -> { },
                HostOptions.defaults());
        session.trace(trace, 50);
        PacedRunner runner = new PacedRunner(session, null);
        runner.setSpeed(PacedRunner.MAX_SPEED);
        // Pause at 1 s exactly (at full speed a chunk lasts ~20 ms of real time, which can be seconds
        // of simulated time, so a pause from outside would land anywhere), edit, then go on to 3 s.
        runner.pauseAt(1_000_000_000L);
        runner.start();
        while (runner.state() == PacedRunner.State.RUNNING || runner.latest().timeNanos() < 1_000_000_000L) {
            Thread.sleep(1);
        }
        EditorModel model = new EditorModel(lab);
        assertTrue(model.apply(ArenaEdits.addWall(lab, 450, 800, 750, 800)));
        runner.edit(model.arena());
        runner.pauseAt(3_000_000_000L);
        runner.start();
        while (runner.state() == PacedRunner.State.RUNNING || runner.latest().timeNanos() < 3_000_000_000L) {
            Thread.sleep(5);
        }
        MainWindow.saveRecording(runner, List.of(), settings, dir);
        assertTrue(runner.stopAndWait(10_000));

        String replay = Files.readAllLines(dir.resolve("replay.txt")).get(1);
        List<String> args = new ArrayList<>(Arrays.asList(replay.split(" ")));
        assertEquals(List.of("java", "-jar", "khepera-sim.jar", "run"), args.subList(0, 4));
        args = new ArrayList<>(args.subList(3, args.size()));
        for (int i = 0; i < args.size(); i++) {
            if (args.get(i).equals("start.arena") || args.get(i).equals("run.edits")) {
                args.set(i, dir.resolve(args.get(i)).toString());
            }
        }
        Path replayTrace = dir.resolve("replay.trace");
        args.addAll(List.of("--seconds", "3", "--trace", replayTrace.toString(), "--quiet"));
        int code = Main.commandLine().execute(args.toArray(new String[0]));
        assertEquals(0, code, args.toString());
        assertEquals(trace.toString(), Files.readString(replayTrace), "the replay's trace is the run's trace");
        assertTrue(Files.readString(dir.resolve("run.edits")).contains("wall 450 800 750 800 8"));
    }
}
