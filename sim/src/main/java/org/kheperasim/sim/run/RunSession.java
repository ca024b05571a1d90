package org.kheperasim.sim.run;

import java.io.Writer;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import org.kheperasim.api.binding.Controllers;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.engine.view.SnapshotListener;
import org.kheperasim.sim.host.ConsoleSink;
import org.kheperasim.sim.host.ControllerHost;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.host.ControllerWindows;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.host.HostedController;
import org.kheperasim.sim.host.Lockstep;
import org.kheperasim.sim.host.StepHost;
import org.kheperasim.sim.trace.TraceWriter;

/**
 * One run that can be driven a piece at a time: the engine, a controller on every robot start of
 * the arena, the lockstep that runs them, and optionally a trace. {@link Simulation} runs a
 * session to its end in one call; the window runs one in chunks against the wall clock, applying
 * an instructor's arena edits between chunks and recording each with its simulated time in an
 * {@link EditLog}, so that the run replays exactly.
 *
 * <p>Every method that advances or edits must be called from one thread, the session's owner
 * (the engine's thread). Chunk boundaries are tick boundaries, so how a run is cut into chunks
 * never changes what it computes.
 */
public final class RunSession implements AutoCloseable {
    private final Arena arena;
    private final long seed;
    private final Settings settings;
    private final Engine engine;
    private final List<HostedController> hosts = new ArrayList<>();
    private final List<ControllerHost> threadHosts = new ArrayList<>();
    private final List<StepHost> stepHosts = new ArrayList<>();
    private final List<SimRobot> robots = new ArrayList<>();
    private final Lockstep lockstep;
    private final String controllerClass;
    private final EditLog edits = new EditLog();
    private TraceWriter trace;
    private long sampleNanos;
    /** Closes the windows the controllers open, when the run ends (in the window mode). */
    private final ControllerWindows windows = ControllerWindows.Installed.get();
    private final List<RobotSetup> setups;
    private final Object windowsMark;
    private boolean closed;

    /**
     * Build a run: load the controller once per robot (a class loader each, so robots share no
     * static state), add the robots in arena order and attach their hosts.
     *
     * @param arena the arena
     * @param controllerName a bundled controller or a class on the classpath
     * @param catalog where controller classes come from
     * @param seed the run's seed
     * @param settings sensor, motor and link settings
     * @param console where controller messages and errors go
     * @param hostOptions hang timeout and test jitter
     */
    public RunSession(Arena arena, String controllerName, ControllerCatalog catalog, long seed, Settings settings,
            ConsoleSink console, HostOptions hostOptions) {
        this(arena, java.util.Collections.nCopies(Objects.requireNonNull(arena, "no arena given").robots().size(),
                new RobotSetup(Objects.requireNonNull(controllerName, "no controller given"), settings)),
                catalog, seed, console, hostOptions);
    }

    /**
     * Set up a run whose robots each have their own controller and settings.
     *
     * @param arena the arena
     * @param setups one per robot of the arena, in order
     * @param catalog where controller classes come from
     * @param seed the run's seed
     * @param console where controller messages and errors go
     * @param hostOptions hang timeout and test jitter
     */
    public RunSession(Arena arena, List<RobotSetup> setups, ControllerCatalog catalog, long seed, ConsoleSink console,
            HostOptions hostOptions) {
        this(arena, setups, catalog, seed, console, hostOptions, null);
    }

    /**
     * As {@link #RunSession(Arena, List, ControllerCatalog, long, ConsoleSink, HostOptions)}, with a
     * recorder that hears every command from the controllers' construction on (a command log).
     */
    RunSession(Arena arena, List<RobotSetup> setups, ControllerCatalog catalog, long seed, ConsoleSink console,
            HostOptions hostOptions, org.kheperasim.sim.engine.view.DriverRecorder recorder) {
        Lockstep.prepare();
        this.arena = Objects.requireNonNull(arena, "no arena given");
        if (setups.size() != arena.robots().size()) {
            throw new IllegalArgumentException("the arena " + arena.name() + " has " + arena.robots().size()
                    + " robots, but " + setups.size() + " robot setups were given");
        }
        this.setups = List.copyOf(setups);
        this.seed = seed;
        this.settings = setups.get(0).settings();
        // The controllers' classes are read and rewritten on another core while the world (its
        // grid's distance field above all) is built: both take a few hundredths of a second at a
        // cold start. Loading runs no code of theirs (their classes are not initialised). When the
        // arena's raster is kept from an earlier run (an evaluation's thousands of episodes), the
        // world takes well under a millisecond, less than starting that thread: load here.
        java.util.concurrent.Executor loader = World.quickToBuild(arena) ? Runnable::run : RunSession::onItsOwnThread;
        java.util.concurrent.CompletableFuture<List<Class<?>>> loading =
                java.util.concurrent.CompletableFuture.supplyAsync(() -> load(catalog, this.setups), loader);
        World world;
        try {
            world = new World(arena);
        } catch (RuntimeException | Error e) {
            try {
                loaded(loading);
            } catch (RuntimeException | Error alsoLoading) {
                e.addSuppressed(alsoLoading);
            }
            throw e;
        }
        List<Class<?>> types = loaded(loading);
        this.engine = new Engine(world, seed);
        if (recorder != null) {
            engine.record(recorder);
        }
        this.windowsMark = windows.mark();
        String cls = null;
        for (int i = 0; i < arena.robots().size(); i++) {
            Pose start = arena.robots().get(i);
            RobotSetup setup = setups.get(i);
            Class<?> type = types.get(i);
            cls = cls == null ? type.getName() : cls;
            String name = arena.robots().size() == 1 ? type.getSimpleName() : type.getSimpleName() + "#" + i;
            SimRobot robot = engine.addRobot(name, start, setup.settings(), arena.robotType(i));
            robot.parameters(setup.parameters());
            boolean stepStyle = Controllers.isStep(type);
            if (onBoard(robot.settings(), stepStyle)) {
                // Before the controller is made: its constructor may already command the robot.
                robot.runOnBoard(stepStyle);
            }
            HostedController host;
            if (stepStyle) {
                StepHost step = new StepHost(robot, type, console, hostOptions);
                stepHosts.add(step);
                host = step;
            } else {
                ControllerHost thread = new ControllerHost(robot, type, console, hostOptions);
                threadHosts.add(thread);
                host = thread;
            }
            engine.attach(robot, host, r -> host.status().name().toLowerCase(Locale.ROOT));
            hosts.add(host);
            robots.add(robot);
        }
        this.controllerClass = cls;
        this.lockstep = new Lockstep(engine, threadHosts, stepHosts, hostOptions.hangTimeoutNanos());
        // Last: a second thread for the world's step (a large swarm) is ended by close().
        engine.threads(hostOptions.engineThreads());
    }

    /**
     * @param modes each robot's controller mode ({@link SimRobot#controlMode})
     * @return the trace header's {@code mode} field: the mode, or each robot's when they differ
     */
    public static String modes(List<String> modes) {
        return modes.stream().distinct().count() == 1 ? modes.get(0) : String.join(" ", modes);
    }

    /**
     * @param settings a robot's settings
     * @param step whether its controller is a step controller
     * @return true when it runs on the robot's own processor: {@code controller.mode} onboard, or auto for a
     *     step controller
     */
    static boolean onBoard(Settings settings, boolean step) {
        String mode = settings.raw("controller.mode");
        return mode.equals("onboard") || mode.equals("auto") && step;
    }

    /** A thread of its own, not a shared pool's, which a controller's parallel streams may keep busy. */
    private static void onItsOwnThread(Runnable work) {
        // Inheriting no thread-local values: the thread building the run may be a controller's.
        Thread t = new Thread(null, work, "khepera-sim loading controllers", 0, false);
        t.setDaemon(true);
        t.start();
    }

    private static List<Class<?>> load(ControllerCatalog catalog, List<RobotSetup> setups) {
        List<Class<?>> types = new ArrayList<>(setups.size());
        for (int i = 0; i < setups.size(); i++) {
            String controller = setups.get(i).controller();
            try {
                types.add(catalog.load(controller));
            } catch (org.kheperasim.api.spi.ControllerException e) {
                if (i == 0 || controller.equals(setups.get(0).controller())) {
                    throw e;
                }
                // A robot's own controller (--robot N:controller=..., or chosen in the window): say whose.
                throw new org.kheperasim.api.spi.ControllerException("robot " + i + "'s controller: "
                        + e.getMessage(), e);
            }
        }
        return types;
    }

    /** The loaded classes, or what loading threw, as it threw it. */
    private static List<Class<?>> loaded(java.util.concurrent.CompletableFuture<List<Class<?>>> loading) {
        try {
            return loading.join();
        } catch (java.util.concurrent.CompletionException e) {
            if (e.getCause() instanceof RuntimeException r) {
                throw r;
            }
            if (e.getCause() instanceof Error err) {
                throw err;
            }
            throw e;
        }
    }

    /**
     * Write a trace of this run. Call before the first {@link #runTo}.
     *
     * @param out where the text goes (closed by {@link #close()})
     * @param sampleMillis sample period, whole ms
     */
    public void trace(Writer out, long sampleMillis) {
        Map<String, String> header = new LinkedHashMap<>();
        header.put("seed", Long.toString(seed));
        header.put("arena", arena.name() + " sha256=" + ArenaFormat.sha256(arena));
        header.put("controller", controllerClass);
        header.put("settings", settings.describe());
        header.put("sample-ms", Long.toString(sampleMillis));
        header.put("mode", modes(robots.stream().map(SimRobot::controlMode).toList()));
        robotTypes(header, arena);
        if (!setups.get(0).parameters().isEmpty()) {
            header.put("parameters", setups.get(0).parameters().toString());
        }
        if (setups.stream().distinct().count() > 1) {
            // Robots with controllers or settings of their own: each is named (one robot's run keeps the old header).
            for (int i = 0; i < setups.size(); i++) {
                header.put("robot-" + i,
                        hosts.get(i).type().getName() + " settings " + setups.get(i).settings().describe());
            }
        }
        trace = new TraceWriter(out, header);
        sampleNanos = sampleMillis * Engine.TICK_NANOS;
        engine.addListener(trace, sampleNanos);
    }

    /**
     * Name each robot's type in a trace's header when one is not the default Khepera I (a run of
     * Khepera Is keeps the header it had).
     *
     * @param header the header fields
     * @param arena the run's arena
     */
    public static void robotTypes(Map<String, String> header, Arena arena) {
        if (arena.robotKinds().stream().allMatch(org.kheperasim.sim.arena.RobotKind::isDefault)) {
            return;
        }
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < arena.robots().size(); i++) {
            org.kheperasim.sim.engine.robot.RobotType t = arena.robotType(i);
            // A calibration is its base robot, measured: the robot and the day say which one.
            sb.append(i == 0 ? "" : " ").append(i).append('=').append(t.name());
            if (t.measured() != null) {
                sb.append('/').append(t.measured().robot()).append('@').append(t.measured().date());
            }
        }
        header.put("robot-types", sb.toString());
    }

    /**
     * @param listener receives snapshots on the session's thread (keep it short, never block)
     * @param periodNanos how often, a whole number of 1 ms ticks
     */
    public void addListener(SnapshotListener listener, long periodNanos) {
        engine.addListener(listener, periodNanos);
    }

    /**
     * Run until simulated time reaches {@code endNanos} or every controller has ended.
     *
     * @param endNanos simulated time, ns
     * @return true while the run can go on (some controller still runs)
     */
    public boolean runTo(long endNanos) {
        return runTo(endNanos, () -> false);
    }

    /**
     * Run until simulated time reaches {@code endNanos}, every controller has ended, or {@code stop}
     * answers true (it is asked about every millisecond of real time; the run then ends at the next
     * tick, so {@link #timeNanos()} may fall short of {@code endNanos}).
     *
     * @param endNanos simulated time, ns
     * @param stop asked whether to stop early; cheap and thread-safe
     * @return true while the run can go on (some controller still runs)
     */
    public boolean runTo(long endNanos, java.util.function.BooleanSupplier stop) {
        if (closed) {
            throw new IllegalStateException("this run has been stopped; reset to start a new one");
        }
        lockstep.run(endNanos, stop);
        return !finished();
    }

    /**
     * Apply an arena edit now, between ticks, and record it with the simulated time.
     *
     * @param edited the edited arena (same size)
     */
    public void edit(Arena edited) {
        engine.edit(edited);
        edits.add(engine.timeNanos(), edited);
    }

    /** @return the edits applied so far, stamped with their simulated times */
    public EditLog edits() {
        return edits;
    }

    /** @return true when every controller has ended */
    public boolean finished() {
        return !engine.anyDriverRunning();
    }

    /** @return simulated time, ns */
    public long timeNanos() {
        return engine.timeNanos();
    }

    /** @return the world now (call between chunks, on the session's thread) */
    public Snapshot snapshot() {
        return engine.snapshot();
    }

    /** @return the engine (for listeners and tests) */
    public Engine engine() {
        return engine;
    }

    /** @return the run's seed */
    public long seed() {
        return seed;
    }

    /** @return the arena the run started from */
    public Arena arena() {
        return arena;
    }

    /** @return where the controllers run, as the trace header's {@code mode} names it ({@link #modes}) */
    public String mode() {
        return modes(robots.stream().map(SimRobot::controlMode).toList());
    }

    /**
     * @return one line for people saying where the controllers run and what that means, e.g.
     *     {@code mode tethered: the controller runs on the host ...}
     */
    public String modeLine() {
        String mode = mode();
        return switch (mode) {
            case SimRobot.TETHERED ->
                    "mode tethered: the controller runs on the host, as robot-link runs it; it sees the"
                    + " values of the serial link's poll cycle (" + settings.raw("link.baud")
                    + " baud) and its commands act"
                    + " after their wire time";
            case SimRobot.ON_BOARD_STEPS, SimRobot.ON_BOARD ->
                    "mode " + mode + ": the controller runs on the robot's own"
                    + " processor; it reads the latest 20 ms sensor scan and its commands act at once (no serial link)";
            default -> "mode, robot by robot: " + mode + " (tethered: through the serial link; onboard: on the robot,"
                    + " reading the latest 20 ms scan)";
        };
    }

    /** @return the controller's class name */
    public String controllerClass() {
        return controllerClass;
    }

    /** @return the controller hosts, in robot order */
    public List<HostedController> hosts() {
        return List.copyOf(hosts);
    }

    /**
     * Stop the controllers and finish the trace (the final sample is written when the end falls
     * on a sample time). Idempotent.
     */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        try {
            if (trace != null && engine.timeNanos() % sampleNanos == 0) {
                trace.onSnapshot(engine.snapshot());
            }
        } finally {
            engine.close();
            lockstep.stopAll();
            windows.closeSince(windowsMark);
            if (trace != null) {
                trace.close();
            }
        }
    }

    /** @return the trace's SHA-256 after {@link #close()}, or null without a trace */
    public String traceSha256() {
        return trace == null ? null : trace.sha256();
    }

    /**
     * @param wallSeconds real time the run took, s
     * @return the run's result (after {@link #close()})
     */
    public RunResult result(double wallSeconds) {
        List<RunResult.RobotResult> results = new ArrayList<>();
        for (int i = 0; i < robots.size(); i++) {
            SimRobot r = robots.get(i);
            HostedController h = hosts.get(i);
            results.add(new RunResult.RobotResult(r.name(), r.x(), r.y(), r.headingDeg(), r.distanceTravelledMm(),
                    r.collisions(), r.visitedPercent(), h.status(),
                    failure(h), r.regionsEntered()));
        }
        return new RunResult(seed, arena.name(), controllerClass, engine.timeNanos() / 1e9, wallSeconds,
                traceSha256(), results, engine.world().capsInRegions(), engine.world().capCount());
    }

    /** @return the first robot's controller status */
    public ControllerStatus status() {
        return hosts.isEmpty() ? ControllerStatus.NOT_STARTED : hosts.get(0).status();
    }

    /**
     * What a robot's controller threw or, when it failed otherwise (hung, broke a rule, ran out of heap), why; null
     * when fine.
     */
    private static String failure(HostedController h) {
        if (h.failure() != null) {
            return h.failure().toString();
        }
        return h.status().failed() ? h.lastError() : null;
    }
}
