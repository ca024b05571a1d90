package org.kheperasim.sim.run;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.function.BooleanSupplier;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.view.SnapshotListener;
import org.kheperasim.sim.host.ConsoleSink;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.trace.LineFileWriter;

/**
 * One headless run: an arena, a controller on every robot start of the arena, a seed, settings and
 * a duration; optionally a trace. The command line, the benchmark and the tests all run through
 * here, so they run the same thing.
 */
public final class Simulation {
    private final Builder b;

    /** The controller output a headless run prints at most, characters (1 MiB). */
    public static final long DEFAULT_OUTPUT_LIMIT = 1L << 20;

    private Simulation(Builder b) {
        this.b = b;
    }

    /** @return a builder with the defaults: 600 s, a random seed, default settings, no trace */
    public static Builder builder() {
        return new Builder();
    }

    /**
     * @return a new seed for a run that was given none (printed, so the run can be repeated); it
     *     needs to differ from run to run, not to be secret, so no SecureRandom (whose providers take
     *     tens of milliseconds to load)
     */
    public static long randomSeed() {
        return java.util.concurrent.ThreadLocalRandom.current().nextLong() & 0xFFFF_FFFFL;
    }

    /** Configures and runs a simulation. */
    public static final class Builder {
        private Arena arena;
        private String controllerName;
        private List<Path> classpath = List.of();
        private Long seed;
        private Settings settings = Settings.defaults();
        private double seconds = 600;
        private Path tracePath;
        private Writer traceWriter;
        private long sampleMillis = 50;
        private ConsoleSink console = line -> { };
        private HostOptions hostOptions = HostOptions.defaults();
        private final List<Subscription> listeners = new ArrayList<>();
        private final List<org.kheperasim.sim.engine.event.EngineEventListener> events = new ArrayList<>();
        private boolean trusted;
        private EditLog edits = new EditLog();
        private BooleanSupplier stop = () -> false;
        private org.kheperasim.sim.engine.view.DriverRecorder recorder;
        private java.util.function.Consumer<RunSession> started = session -> { };
        private long outputLimit = DEFAULT_OUTPUT_LIMIT;
        private final java.util.Map<Integer, String> robotOverrides = new java.util.TreeMap<>();
        private final java.util.Map<Integer, Settings> robotSettingOverrides = new java.util.TreeMap<>();
        private org.kheperasim.api.Parameters parameters = org.kheperasim.api.Parameters.NONE;

        /** @return one setup per robot of the arena: the run's, but where a robot has its own */
        List<RobotSetup> setups() {
            int n = arena.robots().size();
            for (int i : robotOverrides.keySet()) {
                if (i < 0 || i >= n) {
                    throw new IllegalArgumentException("robot " + i
                            + " was given a controller or settings, but the arena "
                            + arena.name() + " has robots 0.." + (n - 1));
                }
            }
            List<RobotSetup> out = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                String c = robotOverrides.get(i);
                Settings s = robotSettingOverrides.get(i);
                out.add(new RobotSetup(c != null ? c : controllerName, s != null ? s : settings, parameters));
            }
            return out;
        }

        /**
         * @param given the numbers handed to every robot's controller ({@link org.kheperasim.api.Parameters}):
         *     a weight vector, a genome
         * @return this
         */
        public Builder parameters(org.kheperasim.api.Parameters given) {
            this.parameters = java.util.Objects.requireNonNull(given);
            return this;
        }

        /** @param arena the arena @return this */
        public Builder arena(Arena arena) {
            this.arena = arena;
            return this;
        }

        /** @param nameOrPath a bundled arena's name or an arena file @return this */
        public Builder arena(String nameOrPath) {
            return arena(ArenaFormat.resolve(nameOrPath));
        }

        /** @param name a bundled controller or a class on the classpath @return this */
        public Builder controller(String name) {
            this.controllerName = name;
            return this;
        }

        /**
         * Give one robot of the arena its own controller and settings (the others keep
         * {@link #controller} and {@link #settings}).
         *
         * @param index the robot, 0 for the arena's first {@code robot} line
         * @param controller its controller, or null to keep the run's
         * @param robotSettings its settings, or null to keep the run's
         * @return this
         */
        public Builder robot(int index, String controller, Settings robotSettings) {
            robotOverrides.put(index, controller);
            robotSettingOverrides.put(index, robotSettings);
            return this;
        }

        /** @param classpath folders and jars with compiled controllers @return this */
        public Builder classpath(List<Path> classpath) {
            this.classpath = List.copyOf(classpath);
            return this;
        }

        /** @param seed the run's seed @return this */
        public Builder seed(long seed) {
            this.seed = seed;
            return this;
        }

        /** @param settings sensor, motor and link settings @return this */
        public Builder settings(Settings settings) {
            this.settings = settings;
            return this;
        }

        /** @param seconds simulated seconds to run @return this */
        public Builder seconds(double seconds) {
            if (!(seconds > 0) || Double.isInfinite(seconds)) {
                throw new IllegalArgumentException("--seconds " + seconds
                        + ": give a positive number of simulated seconds");
            }
            this.seconds = seconds;
            return this;
        }

        /**
         * @param file write the trace there: under its final name, whole lines at least every wall-clock
         *     second ({@link LineFileWriter}), so a run that is killed leaves a readable trace up to then
         * @return this
         */
        public Builder trace(Path file) {
            this.tracePath = file;
            return this;
        }

        /** @param out write the trace to this writer (closed at the end) @return this */
        public Builder trace(Writer out) {
            this.traceWriter = out;
            return this;
        }

        /** @param millis trace sample period, whole ms @return this */
        public Builder sampleMillis(long millis) {
            if (millis < 1 || millis > 3_600_000) {
                throw new IllegalArgumentException("trace sample period " + millis + " ms must lie in 1..3600000 ms"
                        + " (one sample an hour at most)");
            }
            this.sampleMillis = millis;
            return this;
        }

        /** @param console where controller messages and errors go @return this */
        public Builder console(ConsoleSink console) {
            this.console = Objects.requireNonNull(console);
            return this;
        }

        /** @param options hang timeout and test jitter @return this */
        public Builder hostOptions(HostOptions options) {
            this.hostOptions = options;
            return this;
        }

        /**
         * @param trusted true to run the controller uncontained (files, network, reflection allowed;
         *     see docs/controller-rules.md); false, the default, for untrusted code
         * @return this
         */
        public Builder trusted(boolean trusted) {
            this.trusted = trusted;
            return this;
        }

        /** @param listener also receives snapshots, every tick @return this */
        public Builder listener(SnapshotListener listener) {
            return listener(listener, 1);
        }

        /**
         * @param listener also receives snapshots
         * @param periodMillis how often, whole ms (a listener makes the engine stop that often)
         * @return this
         */
        public Builder listener(SnapshotListener listener, long periodMillis) {
            if (periodMillis < 1) {
                throw new IllegalArgumentException("a listener's period of " + periodMillis
                        + " ms must be at least 1 ms");
            }
            this.listeners.add(new Subscription(listener, periodMillis * Engine.TICK_NANOS));
            return this;
        }

        /**
         * @param listener also hears the run's contacts and region entries, at their ticks, in their order
         *     (see {@link org.kheperasim.sim.engine.event.EngineEvents}); it changes nothing of the run
         * @return this
         */
        public Builder events(org.kheperasim.sim.engine.event.EngineEventListener listener) {
            this.events.add(Objects.requireNonNull(listener));
            return this;
        }

        /**
         * @param edits arena edits to apply at their simulated times, as recorded by a run in the
         *     window ({@link RunSession#edits()}); the run then replays that run exactly. Every edit must
         *     fall within the run ({@link EditLog#checkWithin}), else {@link #run()} refuses it.
         * @return this
         */
        public Builder edits(EditLog edits) {
            this.edits = Objects.requireNonNull(edits);
            return this;
        }

        /**
         * @param stop asked about every millisecond of real time while the run goes on; when it answers
         *     true the run ends at the next tick, as if that were its end (e.g. on SIGTERM): the trace is
         *     finished and the result is the run so far
         * @return this
         */
        public Builder stopWhen(BooleanSupplier stop) {
            this.stop = Objects.requireNonNull(stop);
            return this;
        }

        /**
         * @param recorder hears every command the controllers send and when they wake, from their
         *     construction on: a command log that replays the run without them
         *     ({@code org.kheperasim.sim.commandlog})
         * @return this
         */
        public Builder record(org.kheperasim.sim.engine.view.DriverRecorder recorder) {
            this.recorder = recorder;
            return this;
        }

        /**
         * @param started told the session once it is set up (its controllers made), before it runs, after
         *     those given before
         * @return this
         */
        public Builder onStart(java.util.function.Consumer<RunSession> started) {
            this.started = this.started.andThen(Objects.requireNonNull(started));
            return this;
        }

        /**
         * @param chars the most characters of controller output (its lines' text) the console gets in
         *     this run; the rest is dropped, and a note at the end says how much (see {@link BoundedConsole})
         * @return this
         */
        public Builder outputLimit(long chars) {
            if (chars < 0) {
                throw new IllegalArgumentException("an output limit of " + chars + " characters: give 0 or more");
            }
            this.outputLimit = chars;
            return this;
        }

        /** @return the arena this run is set up in (null until given) */
        public Arena arena() {
            return arena;
        }

        /** @return each robot's settings, in the arena's order */
        public List<Settings> robotSettings() {
            return setups().stream().map(RobotSetup::settings).toList();
        }

        /** @return the run's length, simulated s */
        public double seconds() {
            return seconds;
        }

        /** @return the trace's sample period, ms */
        public long sampleMillis() {
            return sampleMillis;
        }

        /** @return the seed this run will use (drawn now if none was given) */
        public long seed() {
            if (seed == null) {
                seed = randomSeed();
            }
            return seed;
        }

        /**
         * Run it.
         *
         * @return what the run produced
         */
        public RunResult run() {
            Objects.requireNonNull(arena, "no arena given");
            Objects.requireNonNull(controllerName, "no controller given");
            return new Simulation(this).execute();
        }
    }

    private record Subscription(SnapshotListener listener, long periodNanos) {
    }

    private RunResult execute() {
        long seed = b.seed();
        long endNanos = (long) StrictMath.rint(b.seconds * 1e9);
        b.edits.checkWithin(endNanos);
        BoundedConsole console = new BoundedConsole(b.console, b.outputLimit);
        RunSession session = new RunSession(b.arena, b.setups(), new ControllerCatalog(b.classpath, b.trusted), seed,
                console, b.hostOptions, b.recorder);
        for (Subscription l : b.listeners) {
            session.addListener(l.listener(), l.periodNanos());
        }
        if (!b.events.isEmpty()) {
            List<org.kheperasim.sim.engine.event.EngineEventListener> all = List.copyOf(b.events);
            org.kheperasim.sim.engine.event.EngineEvents.watch(session.engine(), e -> all.forEach(l -> l.onEvent(e)));
        }
        try {
            if (b.tracePath != null || b.traceWriter != null) {
                Writer w = b.traceWriter;
                if (w == null) {
                    Path parent = b.tracePath.toAbsolutePath().getParent();
                    Files.createDirectories(parent);
                    w = LineFileWriter.open(b.tracePath);
                }
                session.trace(w, b.sampleMillis);
            }
        } catch (IOException e) {
            session.close();
            throw new UncheckedIOException("cannot write the trace " + b.tracePath + ": " + e.getMessage(), e);
        }

        long wallStart = System.nanoTime();
        try {
            b.started.accept(session);
            replay(session, endNanos);
        } finally {
            session.close();
            console.finish();
        }
        double wall = (System.nanoTime() - wallStart) / 1e9;
        return session.result(wall);
    }

    /** Runs to the end, applying each recorded edit at its time; stops early when asked to. */
    private void replay(RunSession session, long endNanos) {
        for (EditLog.Edit e : b.edits.edits()) {
            if (!advance(session, e.timeNanos())) {
                return;
            }
            session.edit(e.arena());
        }
        advance(session, endNanos);
    }

    /**
     * Runs to {@code target} in one go: the run's owner asks the stop request while it watches the
     * controllers (about every millisecond of real time), so a signal is seen soon without handing
     * the turn back and forth between threads every few simulated milliseconds.
     *
     * @return true when the run reached {@code target} and can go on
     */
    private boolean advance(RunSession session, long target) {
        while (session.timeNanos() < target) {
            if (b.stop.getAsBoolean()) {
                return false;
            }
            if (!session.runTo(target, b.stop)) {
                return false;
            }
        }
        return session.timeNanos() == target;
    }
}
