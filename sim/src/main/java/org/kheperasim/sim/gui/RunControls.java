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
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.replay.RobotSeries;
import org.kheperasim.sim.replay.SeriesRecorder;
import org.kheperasim.sim.run.ControllerCatalog;
import org.kheperasim.sim.run.PacedRunner;
import org.kheperasim.sim.run.RunSession;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.task.Score;
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
    /** How long {@code run} runs an arena that sets tasks but no time limit, simulated s. */
    private static final double DEFAULT_RUN_SECONDS = 600;
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
    private volatile LiveScore score;
    private volatile Path runTrace;
    private Settings runSettings = Settings.defaults();
    private boolean stopNotePending;
    private java.util.function.BooleanSupplier ready = () -> true;
    private java.util.function.Supplier<String> stale = () -> null;
    private boolean staleNoted;

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
        return r == null ? null : r.state() == PacedRunner.State.TIME_UP ? "time is up"
                : r.state().name().toLowerCase(Locale.ROOT);
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
        LiveScore s = score;
        return runner == null || s == null ? null : s.text();
    }

    /** @return the score so far, or null without a run or without tasks (tests) */
    Score scoreNow() {
        LiveScore s = score;
        return runner == null || s == null ? null : s.score();
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

    /**
     * @param ready asked before a new run is built (not on resuming): false stops it (the chosen
     *     {@code .java} does not compile); it may compile the controller again
     * @param stale a note to give on resuming a run whose controller's source has changed, or null
     */
    void checks(java.util.function.BooleanSupplier ready, java.util.function.Supplier<String> stale) {
        this.ready = ready;
        this.stale = stale;
    }

    /** Start or resume. */
    void start() {
        PacedRunner r = runner;
        if (r != null && active() && !staleNoted) {
            String note = stale.get();
            if (note != null) {
                staleNoted = true;
                console.note(note);
            }
        }
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
        if (!ready.getAsBoolean()) {
            return false;
        }
        staleNoted = false;
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
        Arena arena = model.arena();
        String own = robotControllers.describe(arena.robots().size());
        double limit = timeLimitSeconds(arena);
        console.note("Run of " + name + (own.isEmpty() ? "" : " (" + own + ")") + " in " + arena.name()
                + ", seed " + runSeed
                + (choices.settings.overrides().isEmpty() ? "" : ", settings " + choices.settings.describe())
                + (limit > 0 ? "; it ends at " + Score.number(limit) + " s ("
                        + (arena.assignment().timeLimitSeconds() > 0
                        ? "the arena's time limit" : "the arena sets tasks but no time limit")
                                + "), as 'run' ends it" : "")
                + "; " + session.modeLine());
        // The score is run's: the start arena's assignment over the engine's own facts (floor covered,
        // regions entered to the millisecond, caps), taken on the engine's thread at the moment shown.
        LiveScore live = arena.assignment().hasTasks() ? new LiveScore(arena) : null;
        score = live;
        if (live != null) {
            live.published(session, true);
        }
        PacedRunner[] self = new PacedRunner[1];
        PacedRunner next = new PacedRunner(session, st -> SwingUtilities.invokeLater(() -> stateChanged(self[0], st)));
        self[0] = next;
        if (live != null) {
            next.addPublishListener(live);
        }
        if (limit > 0) {
            next.endAt((long) StrictMath.rint(limit * 1e9));
        }
        next.setSpeed(choices.speed);
        runner = next;
        changed.run();
        return true;
    }

    /**
     * @return the simulated seconds a run in this arena gets, as {@code run} gives it: the arena's
     *     time limit, or {@code run}'s 600 s when the arena sets tasks but no limit; 0 (no end) for an
     *     arena with neither, to be explored for as long as one likes
     */
    static double timeLimitSeconds(Arena arena) {
        return arena.assignment().timeLimitSeconds() > 0 || arena.assignment().hasTasks()
                ? arena.assignment().secondsOr(DEFAULT_RUN_SECONDS) : 0;
    }

    /**
     * The console and the status bar follow the run: what it does now, how it ended, and in red,
     * until the next run, which controller failed and where (a status bar that still said "loaded,
     * press Start" during a run or after an exception misled).
     *
     * @param r the runner whose state changed (ignored when it is no longer the window's run)
     * @param st the state it changed to
     */
    private void stateChanged(PacedRunner r, PacedRunner.State st) {
        if (r != runner) {
            return;
        }
        String at = String.format(Locale.ROOT, "t = %.3f s", r.latest().timeSeconds());
        String who = RunMessages.described(r.session());
        switch (st) {
            case RUNNING -> status.show("Running " + who + ": F6 pauses, F8 stops.", false);
            case PAUSED -> status.show("Paused at " + at + ": F5 resumes, F7 steps "
                    + PacedRunner.STEP_NANOS / 1_000_000
                    + " ms, F8 stops.", false);
            case FINISHED -> {
                String note = "The controller ended at " + at + ".";
                console.note(note);
                status.show(note + " Start runs it again from the start.", false);
            }
            case TIME_UP -> {
                String sc = score();
                String note = String.format(Locale.ROOT,
                        "Time is up: the arena %s gives a run %s s, and the run ended at %s%s.",
                        r.session().arena().name(), Score.number(timeLimitSeconds(r.session().arena())), at,
                        sc == null ? "" : ", " + sc + ", as 'run' scores it");
                console.note(note);
                status.show(note + " Start runs it again from the start.", false);
            }
            case STOPPED -> {
                if (stopNotePending) {
                    stopNotePending = false;
                    String note = "Stopped at " + at + "; Reset to go back to the start, or Start for a new run.";
                    console.note(note);
                    status.show(note, false);
                }
            }
            case READY -> {
            }
        }
        if (r.failure() != null && st == PacedRunner.State.STOPPED) {
            console.error("the run failed: " + r.failure());
            status.alert("The run failed: " + r.failure() + " (see the console)");
        }
        String failed = RunMessages.failures(r.session().hosts(), r.latest().timeSeconds());
        if (failed != null) {
            status.alert(failed);
        }
        changed.run();
    }

    /**
     * A controller's error line reached the console (a robot may fail while the others run on): the
     * status bar names every controller that failed, and where, as at the run's end.
     *
     * @param line the error line, said as it is when the run knows of no failure (yet)
     */
    void controllerError(org.kheperasim.sim.host.ConsoleLine line) {
        PacedRunner r = runner;
        String failed = r == null ? null : RunMessages.failures(r.session().hosts(), r.latest().timeSeconds());
        status.alert(failed != null ? failed : line.source() + ": " + line.text().lines().findFirst().orElse("")
                + " (see the console)");
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
    List<org.kheperasim.sim.engine.view.RobotView> liveRobots() {
        PacedRunner r = runner;
        return r == null ? List.of() : r.latest().robots();
    }
}
