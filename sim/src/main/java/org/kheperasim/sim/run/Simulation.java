package org.kheperasim.sim.run;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.Settings;
import org.kheperasim.sim.engine.SnapshotListener;
import org.kheperasim.sim.host.ConsoleSink;
import org.kheperasim.sim.host.ControllerHost;

/**
 * One headless run: an arena, a controller on every robot start of the arena, a seed, settings and
 * a duration; optionally a trace. The command line, the benchmark and the tests all run through
 * here, so they run the same thing.
 */
public final class Simulation {
    private final Builder b;

    private Simulation(Builder b) {
        this.b = b;
    }

    /** @return a builder with the defaults: 600 s, a random seed, default settings, no trace */
    public static Builder builder() {
        return new Builder();
    }

    /** @return a new seed for a run that was given none (printed, so the run can be repeated) */
    public static long randomSeed() {
        return new SecureRandom().nextLong() & 0xFFFF_FFFFL;
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
        private ControllerHost.Options hostOptions = ControllerHost.Options.defaults();
        private final List<Subscription> listeners = new ArrayList<>();
        private EditLog edits = new EditLog();

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
                throw new IllegalArgumentException("--seconds " + seconds + ": give a positive number of simulated seconds");
            }
            this.seconds = seconds;
            return this;
        }

        /** @param file write the trace there (atomically: a temporary file renamed at the end) @return this */
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
            if (millis < 1) {
                throw new IllegalArgumentException("trace sample period " + millis + " ms must be at least 1 ms");
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
        public Builder hostOptions(ControllerHost.Options options) {
            this.hostOptions = options;
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
                throw new IllegalArgumentException("a listener's period of " + periodMillis + " ms must be at least 1 ms");
            }
            this.listeners.add(new Subscription(listener, periodMillis * Engine.TICK_NANOS));
            return this;
        }

        /**
         * @param edits arena edits to apply at their simulated times, as recorded by a run in the
         *     window ({@link RunSession#edits()}); the run then replays that run exactly
         * @return this
         */
        public Builder edits(EditLog edits) {
            this.edits = Objects.requireNonNull(edits);
            return this;
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
        RunSession session = new RunSession(b.arena, b.controllerName, new ControllerCatalog(b.classpath), seed,
                b.settings, b.console, b.hostOptions);
        for (Subscription l : b.listeners) {
            session.addListener(l.listener(), l.periodNanos());
        }
        Path traceTemp = null;
        try {
            if (b.tracePath != null || b.traceWriter != null) {
                Writer w = b.traceWriter;
                if (w == null) {
                    Path parent = b.tracePath.toAbsolutePath().getParent();
                    Files.createDirectories(parent);
                    traceTemp = Files.createTempFile(parent, b.tracePath.getFileName().toString(), ".part");
                    w = Files.newBufferedWriter(traceTemp, StandardCharsets.UTF_8);
                }
                session.trace(w, b.sampleMillis);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the trace " + b.tracePath + ": " + e.getMessage(), e);
        }

        long endNanos = (long) StrictMath.rint(b.seconds * 1e9);
        long wallStart = System.nanoTime();
        try {
            session.runTo(endNanos, b.edits);
        } finally {
            session.close();
            if (traceTemp != null) {
                moveIntoPlace(traceTemp, b.tracePath);
            }
        }
        double wall = (System.nanoTime() - wallStart) / 1e9;
        return session.result(wall);
    }

    private static void moveIntoPlace(Path temp, Path target) {
        try {
            try {
                Files.move(temp, target, java.nio.file.StandardCopyOption.REPLACE_EXISTING,
                        java.nio.file.StandardCopyOption.ATOMIC_MOVE);
            } catch (java.nio.file.AtomicMoveNotSupportedException e) {
                Files.move(temp, target, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot move the trace into place at " + target + ": " + e.getMessage(), e);
        }
    }
}
