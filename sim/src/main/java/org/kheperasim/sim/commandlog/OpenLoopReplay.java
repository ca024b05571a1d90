package org.kheperasim.sim.commandlog;

import java.io.Writer;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kheperasim.api.GripperState;
import org.kheperasim.link.timing.PollStep;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.RobotDriver;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.SnapshotListener;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.trace.TraceWriter;

/**
 * A run made again from its command log, open loop: the same arena, seed and settings, and instead
 * of each controller a driver that wakes when the controller woke and sends what it sent, when it
 * sent it, taking the vision turret's images where the controller read them (the trace shows them).
 * No controller code runs. The engine is deterministic and a controller acts on the world
 * only through those commands, so the replay computes the same world, byte for byte in its trace
 * (ReplayExactnessTest holds it to that over every bundled arena and controller): what the run scored is
 * computed here, by whoever replays it, never taken from the run.
 *
 * <p>The log is consumed in the engine's order: at each driver's turn, the events up to that
 * driver's next wake. A log that does not fit the run (a wake of another robot where this one's
 * was due, a robot that does not exist, a wrong seed) stops the replay with
 * {@link ReplayMismatchException}: the run that wrote it was not the run it claims to be.
 */
public final class OpenLoopReplay {
    /**
     * What the replayer asked the run to be: the log must say the same.
     *
     * @param arena        the arena
     * @param seed         the seed
     * @param endNanos     where the run ends, simulated ns
     * @param sampleMillis the trace's sample period, ms
     * @param settings     each robot's settings, in the arena's order
     */
    public record Run(Arena arena, long seed, long endNanos, long sampleMillis, List<Settings> settings) {
        /** Copies the list. */
        public Run {
            settings = List.copyOf(settings);
        }
    }

    /**
     * What the replay computed.
     *
     * @param result   the run's result as the replay computed it (a robot's status says only whether its
     *                 driver ended: {@code FINISHED}, or {@code STOPPED} at the run's end)
     * @param claim    the run's own result, as it wrote it at the end of its log (JSON)
     * @param events   the log's events
     */
    public record Outcome(RunResult result, String claim, long events) {
    }

    private OpenLoopReplay() {
    }

    /**
     * @param run   what the run was asked to be
     * @param log   its command log
     * @param trace where the replay's trace goes (closed at the end)
     * @return the replayed result and the run's claim
     * @throws ReplayMismatchException if the log does not belong to this run or does not fit it
     * @throws LogFormatException if the log is torn or malformed
     */
    public static Outcome replay(Run run, CommandLogReader log, Writer trace) {
        return replay(run, log, trace, null);
    }

    /**
     * As {@link #replay(Run, CommandLogReader, Writer)}, telling a recorder what the replay's drivers do
     * (a test's check that the replay does what the log says, in the same order).
     */
    static Outcome replay(Run run, CommandLogReader log, Writer trace,
            org.kheperasim.sim.engine.view.DriverRecorder recorder) {
        return replay(run, log, trace, recorder, null, 0);
    }

    /**
     * As {@link #replay(Run, CommandLogReader, Writer)}, with one more listener of the replay's
     * snapshots (grade's web page of the run, at its own period; like any listener it does not change
     * what the replay computes).
     *
     * @param listener     also receives the replay's snapshots
     * @param periodMillis how often, simulated ms, ≥ 1
     */
    public static Outcome replay(Run run, CommandLogReader log, Writer trace, SnapshotListener listener,
            long periodMillis) {
        return replay(run, log, trace, null, listener, periodMillis);
    }

    private static Outcome replay(Run run, CommandLogReader log, Writer trace,
            org.kheperasim.sim.engine.view.DriverRecorder recorder,
            SnapshotListener listener, long periodMillis) {
        LogHeader h = log.header();
        check(run, h);
        Engine engine = new Engine(new World(run.arena()), run.seed());
        if (recorder != null) {
            engine.record(recorder);
        }
        List<SimRobot> robots = new ArrayList<>();
        List<Driver> drivers = new ArrayList<>();
        for (int i = 0; i < h.robots().size(); i++) {
            SimRobot robot = engine.addRobot(h.robots().get(i).name(), run.arena().robots().get(i),
                    run.settings().get(i),
                    run.arena().robotType(i));
            try {
                robot.controlMode(h.robots().get(i).mode());
            } catch (IllegalArgumentException e) {
                throw new ReplayMismatchException("robot " + i + ": " + e.getMessage());
            }
            Driver d = new Driver(i);
            engine.attach(robot, d, r -> d.ended ? "finished" : "replay");
            robots.add(robot);
            drivers.add(d);
        }
        Map<String, String> header = traceHeader(run, h);
        TraceWriter writer = new TraceWriter(trace, header);
        long sampleNanos = run.sampleMillis() * Engine.TICK_NANOS;
        engine.addListener(writer, sampleNanos);
        if (listener != null) {
            engine.addListener(listener, periodMillis * Engine.TICK_NANOS);
        }
        engine.setEnd(run.endNanos());
        Player player = new Player(log, engine, robots, drivers);
        String claim;
        try {
            player.start();
            RobotDriver next;
            while ((next = engine.advance()) != null) {
                Driver d = (Driver) next;
                player.turn(d, engine.timeNanos() / Engine.TICK_NANOS);
            }
            if (engine.timeNanos() % sampleNanos == 0) {
                writer.onSnapshot(engine.snapshot());
            }
            claim = player.rest();
        } finally {
            writer.close();
        }
        List<RunResult.RobotResult> results = new ArrayList<>();
        for (int i = 0; i < robots.size(); i++) {
            SimRobot r = robots.get(i);
            results.add(new RunResult.RobotResult(r.name(), r.x(), r.y(), r.headingDeg(), r.distanceTravelledMm(),
                    r.collisions(), r.visitedPercent(),
                    drivers.get(i).ended ? ControllerStatus.FINISHED : ControllerStatus.STOPPED,
                    null, r.regionsEntered()));
        }
        RunResult result = new RunResult(run.seed(), run.arena().name(), h.robots().get(0).controllerClass(),
                engine.timeNanos() / 1e9, 0, writer.sha256(), results, engine.world().capsInRegions(),
                engine.world().capCount());
        return new Outcome(result, claim, player.events);
    }

    /** The header a run writes in its trace (see {@code RunSession.trace}), from the log's robots. */
    private static Map<String, String> traceHeader(Run run, LogHeader h) {
        Map<String, String> header = new LinkedHashMap<>();
        header.put("seed", Long.toString(run.seed()));
        header.put("arena", run.arena().name() + " sha256=" + ArenaFormat.sha256(run.arena()));
        header.put("controller", h.robots().get(0).controllerClass());
        header.put("settings", run.settings().get(0).describe());
        header.put("sample-ms", Long.toString(run.sampleMillis()));
        header.put("mode", org.kheperasim.sim.run.RunSession.modes(
                h.robots().stream().map(LogHeader.Robot::mode).toList()));
        org.kheperasim.sim.run.RunSession.robotTypes(header, run.arena());
        boolean alike = true;
        for (LogHeader.Robot r : h.robots()) {
            alike &= r.controllerClass().equals(h.robots().get(0).controllerClass())
                    && r.settings().equals(h.robots().get(0).settings());
        }
        if (!alike) {
            for (int i = 0; i < h.robots().size(); i++) {
                header.put("robot-" + i,
                        h.robots().get(i).controllerClass() + " settings " + run.settings().get(i).describe());
            }
        }
        return header;
    }

    private static void check(Run run, LogHeader h) {
        String arena = run.arena().name() + " sha256=" + ArenaFormat.sha256(run.arena());
        if (h.seed() != run.seed()) {
            throw new ReplayMismatchException("the log is of seed " + h.seed()
                    + ", the run was asked for seed " + run.seed());
        }
        if (!h.arena().equals(arena)) {
            throw new ReplayMismatchException("the log is of arena " + h.arena() + ", the run was asked for " + arena);
        }
        if (h.endNanos() != run.endNanos() || h.sampleMillis() != run.sampleMillis()) {
            throw new ReplayMismatchException("the log is of a run to " + h.endNanos() + " ns sampled every "
                    + h.sampleMillis()
                    + " ms, the run was asked to " + run.endNanos() + " ns every " + run.sampleMillis() + " ms");
        }
        if (h.robots().size() != run.arena().robots().size() || run.settings().size() != h.robots().size()) {
            throw new ReplayMismatchException("the log has " + h.robots().size() + " robots, the arena "
                    + run.arena().robots().size());
        }
        for (int i = 0; i < h.robots().size(); i++) {
            if (!h.robots().get(i).settings().equals(run.settings().get(i).describe())) {
                throw new ReplayMismatchException("robot " + i + "'s settings in the log are '"
                        + h.robots().get(i).settings()
                        + "', the run was asked for '" + run.settings().get(i).describe() + "'");
            }
            if (!h.robots().get(i).controllerClass().matches("[\\p{L}_$][\\p{L}\\p{N}_$.]*")
                    || !h.robots().get(i).name().matches("[\\p{L}\\p{N}_$#.]+")) {
                throw new ReplayMismatchException("robot " + i
                        + "'s controller or name in the log is not a class name");
            }
        }
    }

    /** A robot's driver in the replay: wakes when the log says, and does nothing itself (the player sends). */
    private static final class Driver implements RobotDriver {
        final int robot;
        long wake;
        boolean ended;

        Driver(int robot) {
            this.robot = robot;
        }

        @Override
        public long wakeNanos() {
            return ended ? Long.MAX_VALUE : wake;
        }

        @Override
        public void grant(long limitNanos) {
            // The player applies the turn's commands when the engine hands this driver back.
        }
    }

    /** Walks the log in step with the engine, applying each command to its robot. */
    private static final class Player {
        private final CommandLogReader log;
        private final Engine engine;
        private final List<SimRobot> robots;
        private final List<Driver> drivers;
        long events;

        Player(CommandLogReader log, Engine engine, List<SimRobot> robots, List<Driver> drivers) {
            this.log = log;
            this.engine = engine;
            this.robots = robots;
            this.drivers = drivers;
        }

        /** The commands sent before the run started (in constructors), then every driver's first wake. */
        void start() {
            boolean[] told = new boolean[drivers.size()];
            int left = drivers.size();
            while (left > 0) {
                CommandLogReader.Event e = next("the drivers' wakes at the start");
                if (e instanceof CommandLogReader.Wake w) {
                    if (!w.initial() || told[w.robot()]) {
                        throw diverged("a wake at the start was expected for each robot once", w);
                    }
                    told[w.robot()] = true;
                    left--;
                    set(drivers.get(w.robot()), w, 0);
                } else {
                    act(e);
                }
            }
        }

        /** A driver's turn at {@code tick}: the commands up to its next wake. */
        void turn(Driver d, long tick) {
            while (true) {
                CommandLogReader.Event e = next("robot " + d.robot + "'s turn at tick " + tick);
                if (e instanceof CommandLogReader.Wake w) {
                    if (w.initial() || w.robot() != d.robot) {
                        throw diverged("robot " + d.robot + " had the turn at tick " + tick, w);
                    }
                    set(d, w, tick);
                    return;
                }
                act(e);
            }
        }

        /** After the run: the stops at its end, then the run's own result. */
        String rest() {
            while (true) {
                CommandLogReader.Event e = log.next();
                if (e == null) {
                    throw new LogFormatException(log.lineNumber(), "the log ends without the run's result");
                }
                if (e instanceof CommandLogReader.Claim c) {
                    if (log.next() != null) {
                        throw new LogFormatException(log.lineNumber(), "events after the run's result");
                    }
                    return c.json();
                }
                if (e instanceof CommandLogReader.Wake w) {
                    throw diverged("the run was over", w);
                }
                act(e);
            }
        }

        private CommandLogReader.Event next(String where) {
            CommandLogReader.Event e = log.next();
            if (e == null || e instanceof CommandLogReader.Claim) {
                throw new ReplayMismatchException("the log ends (line " + log.lineNumber()
                        + ") where the run goes on: " + where);
            }
            events++;
            return e;
        }

        private void set(Driver d, CommandLogReader.Wake w, long tick) {
            if (w.ended()) {
                d.ended = true;
            } else if (w.ticks() < 0 || w.ticks() > (Long.MAX_VALUE / Engine.TICK_NANOS) - tick - 1) {
                throw diverged("a wake must lie ahead", w);
            } else {
                d.wake = (tick + w.ticks()) * Engine.TICK_NANOS;
            }
        }

        private void act(CommandLogReader.Event e) {
            if (e instanceof CommandLogReader.Stop s) {
                robots.get(s.robot()).emergencyStop();
            } else if (e instanceof CommandLogReader.EarlyEnd q) {
                // The run was stopped where the wall clock decided: it ended there, and so does its replay.
                engine.stopAt(q.nanos());
            } else if (e instanceof CommandLogReader.Command c) {
                SimRobot r = robots.get(c.robot());
                switch (c.kind()) {
                    case 'v' -> r.controls().commandSpeeds(c.now(), c.a(), c.b());
                    case 'p' -> r.controls().commandPositions(c.now(), c.a(), c.b());
                    case 'a' -> r.controls().commandArm(c.now(), c.a());
                    case 'f' -> r.controls()
                            .commandFingers(c.now(), c.a() == 1 ? GripperState.CLOSED : GripperState.OPEN);
                    case 'r' -> read(r, c.now(), c.a());
                    case 'i' -> r.vision().image(c.now()); // the same image, at the same moment: the trace shows it
                    default -> throw new IllegalStateException("command " + c.kind());
                }
            } else {
                throw new IllegalStateException("event " + e);
            }
        }

        /** The same read, for its one effect: the reply it brought in early. */
        private void read(SimRobot r, long now, int step) {
            PollStep[] steps = PollStep.values();
            if (step < 0 || step >= steps.length) {
                throw new LogFormatException(log.lineNumber(), "no poll reply " + step);
            }
            switch (steps[step]) {
                case PROXIMITY -> r.controls().visibleProximity(now, 0);
                case LIGHT -> r.controls().visibleLight(now, 0);
                default -> r.controls().visibleEncoderLeft(now);
            }
        }

        private ReplayMismatchException diverged(String expected, CommandLogReader.Wake w) {
            return new ReplayMismatchException("the log does not follow the run at line " + log.lineNumber()
                    + ": " + expected
                    + ", but the log holds a wake of robot " + w.robot());
        }
    }
}
