package org.kheperasim.sim.gui;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.Settings;
import org.kheperasim.sim.engine.Snapshot;

import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.replay.RobotSeries;
import org.kheperasim.sim.replay.SeriesRecorder;
import org.kheperasim.sim.run.ControllerCatalog;
import org.kheperasim.sim.run.PacedRunner;
import org.kheperasim.sim.run.RunSession;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.trace.LineFileWriter;

/**
 * The window's live run: Start, Pause, Step, Stop, Reset, the speed, and edits forwarded to the
 * running engine. The run lives on a {@link PacedRunner}'s thread; this only sends it commands and
 * reads its latest snapshot, so the engine never waits on the screen. Every run keeps its trail,
 * its samples for the plot, and its trace (100 ms) in a temporary file for a run recording.
 */
final class RunControls implements SnapshotSource {
    /** Simulated time between the trail's points, ns. */
    private static final long TRAIL_PERIOD_NANOS = 20 * Engine.TICK_NANOS;
    /** Simulated time between the plot's samples, ns. */
    private static final long SERIES_PERIOD_NANOS = 100 * Engine.TICK_NANOS;

    private final EditorModel model;
    private final ConsolePanel console;
    private final StatusBar status;
    private final RunChoices choices;
    private final RobotControllers robotControllers;
    private final Runnable changed;
    private final TrailRecorder trail = new TrailRecorder();
    private volatile SeriesRecorder series = new SeriesRecorder();
    private volatile PacedRunner runner;
    private volatile org.kheperasim.sim.task.TaskProgress progress;
    private volatile Path runTrace;
    private Settings runSettings = Settings.defaults();
    private boolean stopNotePending;

    /**
     * @param changed called on the event thread when the run's state changed or the run was discarded
     */
    RunControls(EditorModel model, ConsolePanel console, StatusBar status, RunChoices choices,
            RobotControllers robotControllers, Runnable changed) {
        this.model = model;
        this.console = console;
        this.status = status;
        this.choices = choices;
        this.robotControllers = robotControllers;
        this.changed = changed;
    }

    @Override
    public Snapshot snapshot() {
        PacedRunner r = runner;
        return r == null ? null : r.latest();
    }

    @Override
    public String state() {
        PacedRunner r = runner;
        return r == null ? null : r.state().name().toLowerCase(Locale.ROOT);
    }

    @Override
    public float[] trail(int robot) {
        return trail.trail(robot);
    }

    @Override
    public RobotSeries series(int robot) {
        return series.series(robot);
    }

    /** @return the assignment's score so far in words, or null without a run or without tasks */
    String score() {
        org.kheperasim.sim.task.TaskProgress p = progress;
        if (runner == null || p == null) {
            return null;
        }
        org.kheperasim.sim.task.Score score = p.score();
        return score.parts().isEmpty() ? null : "score " + score.summary();
    }

    /** @return the runner, or null */
    PacedRunner runner() {
        return runner;
    }

    /** @return the state of the runner, or null without one */
    PacedRunner.State runState() {
        PacedRunner r = runner;
        return r == null ? null : r.state();
    }

    /** @return true while a run is ready, running or paused */
    boolean active() {
        PacedRunner.State s = runState();
        return s == PacedRunner.State.READY || s == PacedRunner.State.RUNNING || s == PacedRunner.State.PAUSED;
    }

    /** @return the settings the current run started with */
    Settings runSettings() {
        return runSettings;
    }

    /** @return the file the current run's trace goes to, or null */
    Path runTrace() {
        return runTrace;
    }

    /** @param s simulated seconds per real second */
    void setSpeed(double s) {
        choices.speed = s;
        PacedRunner r = runner;
        if (r != null) {
            r.setSpeed(s);
        }
    }

    /** Start or resume. */
    void start() {
        if (ensureRunner()) {
            runner.start();
        }
    }

    void pause() {
        PacedRunner r = runner;
        if (r != null) {
            r.pause();
        }
    }

    void step() {
        if (ensureRunner()) {
            runner.step();
        }
    }

    void stop() {
        PacedRunner r = runner;
        if (r != null) {
            // The runner stops at the end of its current chunk (up to seconds of simulated time at full
            // speed): the note says where it stopped once it has, so it agrees with the clock.
            stopNotePending = true;
            r.stop();
        }
    }

    void reset() {
        discard();
        console.note("Reset: the robot is back at its start; the controller is loaded afresh at Start.");
    }

    /** Forget the run (the robot is drawn at its start again). */
    void discard() {
        stopNotePending = false;
        PacedRunner r = runner;
        runner = null;
        if (r != null) {
            r.stop();
        }
        trail.clear();
        series = new SeriesRecorder();
        changed.run();
    }

    /** @param edited the arena after an edit, applied to the running engine at its current time */
    void forwardEdit(Arena edited) {
        PacedRunner r = runner;
        if (r != null && active()) {
            r.edit(edited);
        }
    }

    private boolean ensureRunner() {
        PacedRunner r = runner;
        if (r != null && active()) {
            return true;
        }
        if (r != null) {
            r.stop();
        }
        long runSeed = choices.seed != null ? choices.seed : Simulation.randomSeed();
        RunSession session;
        String name = choices.controllerName;
        try {
            session = new RunSession(model.arena(), robotControllers.setups(model.arena().robots().size(), name,
                    choices.settings), new ControllerCatalog(choices.classpath, choices.trusted), runSeed, console,
                    HostOptions.defaults());
        } catch (RuntimeException e) {
            console.error("cannot start " + name + ": " + e.getMessage());
            status.show("Cannot start: " + e.getMessage(), true);
            return false;
        }
        runSettings = choices.settings;
        keepTrace(session);
        trail.clear();
        series = new SeriesRecorder();
        session.addListener(trail, TRAIL_PERIOD_NANOS);
        session.addListener(series, SERIES_PERIOD_NANOS);
        org.kheperasim.sim.task.TaskProgress tasks = new org.kheperasim.sim.task.TaskProgress(model.arena());
        session.addListener(tasks, TRAIL_PERIOD_NANOS);
        progress = tasks;
        String own = robotControllers.describe(model.arena().robots().size());
        console.note("Run of " + name + (own.isEmpty() ? "" : " (" + own + ")") + " in " + model.arena().name()
                + ", seed " + runSeed + (choices.settings.overrides().isEmpty() ? "" : ", settings " + choices.settings.describe()));
        PacedRunner next = new PacedRunner(session, st -> SwingUtilities.invokeLater(this::stateChanged));
        next.setSpeed(choices.speed);
        runner = next;
        changed.run();
        return true;
    }

    private void stateChanged() {
        PacedRunner r = runner;
        if (r != null && r.state() == PacedRunner.State.FINISHED) {
            console.note("The controller ended at t = " + String.format(Locale.ROOT, "%.3f s", r.latest().timeSeconds()) + ".");
        }
        if (r != null && stopNotePending && r.state() == PacedRunner.State.STOPPED) {
            stopNotePending = false;
            console.note("Stopped at t = " + String.format(Locale.ROOT, "%.3f s", r.latest().timeSeconds())
                    + "; Reset to go back to the start, or Start for a new run.");
        }
        if (r != null && r.failure() != null) {
            console.error("the run failed: " + r.failure());
        }
        changed.run();
    }

    /** Every run keeps its trace (100 ms samples) in a temporary file, so a recording holds what it did. */
    private void keepTrace(RunSession session) {
        try {
            Path file = Files.createTempFile("khepera-window-run-", ".trace");
            file.toFile().deleteOnExit();
            session.trace(LineFileWriter.open(file), 100);
            runTrace = file;
        } catch (IOException e) {
            runTrace = null;
            console.note("this run keeps no trace (" + e.getMessage() + "); a recording of it cannot be verified");
        }
    }

    /** Stop the run for good (the window closes). */
    void close() {
        PacedRunner r = runner;
        runner = null;
        if (r != null) {
            r.stop();
        }
    }

    /** @return the robots of the live run (for the editor's checks), or none */
    List<org.kheperasim.sim.engine.RobotView> liveRobots() {
        PacedRunner r = runner;
        return r == null ? List.of() : r.latest().robots();
    }
}
