package org.kheperasim.sim.testkit;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import org.kheperasim.sim.arena.ArenaFiles;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.files.AtomicFiles;
import org.kheperasim.sim.files.TextFiles;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.replay.ReplayFiles;
import org.kheperasim.sim.run.ControllerCatalog;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.trace.TraceDiff;
import org.kheperasim.sim.trace.TraceFormatException;
import org.kheperasim.sim.trace.TraceReader;
import org.kheperasim.sim.web.RunOutcome;
import org.kheperasim.sim.web.RunPage;

/**
 * The simulator as the {@code testing} module uses it, in one place: arenas, settings, runs (with the
 * engine's contact events), traces, recordings, the run page and the console. The testing module reaches
 * the simulator only through this package (an ArchUnit rule of that module keeps it so), so the engine
 * can be reorganised without touching it.
 */
public final class TestKit {
    private TestKit() {
    }

    // ------------------------------------------------------------------ arenas

    /**
     * @param nameOrPath a bundled arena's name or an arena file's path (an existing file wins)
     * @return the arena
     * @throws IllegalArgumentException when it is neither
     */
    public static KitArena arena(String nameOrPath) {
        return new KitArena(ArenaFormat.resolve(nameOrPath));
    }

    /** @param file an arena file ({@code .arena}, or a WSU Khepera Simulator world file) @return the arena */
    public static KitArena arenaFile(Path file) {
        return new KitArena(ArenaFiles.load(file));
    }

    /** @param file an {@code .arena} file (a recording's {@code start.arena}) @return the arena */
    public static KitArena arenaFormatFile(Path file) {
        return new KitArena(ArenaFormat.load(file));
    }

    /** @return the bundled arenas' names */
    public static List<String> bundledArenas() {
        return ArenaFormat.bundledNames();
    }

    /** @param name a bundled arena's name @return the arena */
    public static KitArena bundledArena(String name) {
        return new KitArena(ArenaFormat.loadBundled(name));
    }

    /**
     * @param trace a trace file
     * @param name the arena's name its header gives
     * @param sha256 the arena's SHA-256 its header gives, or null
     * @return the arena lying beside the trace that matches, as the replay finds it
     */
    public static Optional<KitArena> arenaBeside(Path trace, String name, String sha256) {
        ReplayFiles.Beside b = ReplayFiles.arenaBeside(trace, name, sha256);
        return b == null ? Optional.empty() : Optional.of(new KitArena(b.arena()));
    }

    /**
     * @param arena an arena
     * @param folder where to write {@code NAME.arena}
     * @return the file
     */
    public static Path saveArena(KitArena arena, Path folder) {
        Path file = folder.resolve(arena.name() + ArenaFormat.EXTENSION);
        ArenaFormat.save(arena.arena, file);
        return file;
    }

    // ------------------------------------------------------------------ controllers

    /** @return the package of the bundled controllers */
    public static String bundledControllerPackage() {
        return ControllerCatalog.BUNDLED_PACKAGE;
    }

    /** @return the bundled controllers' simple names */
    public static List<String> bundledControllers() {
        return List.copyOf(ControllerCatalog.bundled());
    }

    // ------------------------------------------------------------------ runs

    /**
     * Run headless, as {@code khepera-sim run --trace} does with the same options (the same trace, byte for
     * byte), and hear the engine's contact events meanwhile.
     *
     * @param spec what to run
     * @param console hears each console line on the thread that printed it (a controller's, for its errors)
     * @return what it made
     * @throws org.kheperasim.api.spi.ControllerException when a controller cannot run at all
     */
    public static KitResult run(KitRunSpec spec, Consumer<KitConsoleLine> console) {
        StringWriter trace = new StringWriter();
        ContactLog contacts = new ContactLog(spec.controllers().size());
        Simulation.Builder b = Simulation.builder().arena(spec.arena().arena).controller(spec.controllers().get(0))
                .classpath(spec.classpath()).seed(spec.seed()).seconds(spec.seconds())
                .settings(spec.settings().get(0).settings).sampleMillis(spec.sampleMillis()).trusted(spec.trusted())
                .hostOptions(HostOptions.defaults().withHangTimeout((long) (spec.hangTimeoutSeconds() * 1e9)))
                .trace(trace).events(contacts).console(line -> console.accept(kit(line)));
        for (int i = 1; i < spec.controllers().size(); i++) {
            boolean ownController = !spec.controllers().get(i).equals(spec.controllers().get(0));
            boolean ownSettings = !spec.settings().get(i).equals(spec.settings().get(0));
            if (ownController || ownSettings) {
                b.robot(i, ownController ? spec.controllers().get(i) : null,
                        ownSettings ? spec.settings().get(i).settings : null);
            }
        }
        if (spec.edits() != null) {
            b.edits(spec.edits().log);
        }
        RunResult result = b.run();
        long end = (long) StrictMath.rint(result.simulatedSeconds() * 1e9);
        List<KitResult.Robot> robots = new ArrayList<>();
        for (int i = 0; i < result.robots().size(); i++) {
            RunResult.RobotResult r = result.robots().get(i);
            robots.add(new KitResult.Robot(r.name(), KitResult.Status.valueOf(r.status().name()), r.failure(),
                    r.collisions(), r.distanceMm(), r.visitedPercent(), r.regionsEntered(), contacts.contacts(i, end)));
        }
        KitScore score = KitScore.of(org.kheperasim.sim.task.Score.of(spec.arena().arena, RunFacts.of(result)));
        return new KitResult(trace.toString(), result.simulatedSeconds(), robots, score);
    }

    private static KitConsoleLine kit(ConsoleLine line) {
        return new KitConsoleLine(line.timeNanos(), line.source(), line.kind() == ConsoleLine.Kind.ERROR, line.text(),
                line.format());
    }

    /**
     * The score of a recorded run, from what a trace knows (no floor coverage).
     *
     * @param arena the arena
     * @param seconds the run's length, s
     * @param regionsEntered the regions any robot entered, with the first time, s
     * @param capsIn how many caps lie in each region at the end
     * @return the score
     */
    public static KitScore score(KitArena arena, double seconds, Map<String, Double> regionsEntered,
            Map<String, Integer> capsIn) {
        return KitScore.of(org.kheperasim.sim.task.Score.of(arena.arena,
                new RunFacts(seconds, regionsEntered, 0, capsIn, arena.capCount())));
    }

    /**
     * @param relativeRad the direction of a touched thing seen from the robot's centre, radians
     *     counter-clockwise from straight ahead
     * @return the side of the robot it lies on, as the engine names it ({@code FRONT}, {@code FRONT_LEFT}, ...)
     */
    public static String sideOf(double relativeRad) {
        return org.kheperasim.sim.engine.view.Contact.ofAngle(relativeRad).name();
    }

    // ------------------------------------------------------------------ traces and files

    /**
     * @param file a trace file
     * @param maxBytes the largest accepted
     * @return its text
     * @throws RuntimeException naming the file when it is too large, not UTF-8 or not a file
     */
    public static String readTrace(Path file, long maxBytes) {
        return TextFiles.readUtf8(file, maxBytes, "trace",
                (line, what) -> new TraceFormatException(file.toString(), line, what));
    }

    /**
     * @param text a trace
     * @param source how errors name it
     * @return its header, checked by the simulator's reader (a damaged trace is refused with its line)
     */
    public static Map<String, String> traceHeader(String text, String source) {
        return TraceReader.parse(text, source).header();
    }

    /**
     * @param source the trace
     * @param line 1-based line, 0 for the whole file
     * @param what what is wrong
     * @return the error the simulator gives for a bad trace
     */
    public static RuntimeException traceError(String source, int line, String what) {
        return new TraceFormatException(source, line, what);
    }

    /** @param recorded a trace @param now another @return where they differ */
    public static KitTraceDiff compareTraces(String recorded, String now) {
        TraceDiff.Result d = TraceDiff.compare(recorded, now);
        return new KitTraceDiff(d.header(), d.firstSample(), d.samples());
    }

    /**
     * Write a file at once or not at all (a temporary file, then a rename).
     *
     * @param file the file
     * @param text its text
     * @throws IOException when it cannot be written
     */
    public static void writeAtomically(Path file, String text) throws IOException {
        AtomicFiles.write(file, text);
    }

    /**
     * Write the run's web page (to watch it in a browser, no simulator needed).
     *
     * @param trace the trace file
     * @param arena its arena
     * @param title the page's heading
     * @param failures the controllers that failed
     * @param page the page to write
     */
    public static void writeRunPage(Path trace, KitArena arena, String title, List<KitFailure> failures, Path page) {
        List<RunOutcome.Failure> f = failures.stream()
                .map(x -> new RunOutcome.Failure(x.robot(), x.seconds(), x.status(), x.message())).toList();
        RunPage.write(trace, arena.arena, new RunOutcome(title, f, null), page);
    }
}
