package org.kheperasim.testing;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.LongFunction;
import org.kheperasim.sim.testkit.KitArena;
import org.kheperasim.sim.testkit.KitEdits;
import org.kheperasim.sim.testkit.KitRegion;
import org.kheperasim.sim.testkit.KitSettings;
import org.kheperasim.sim.testkit.TestKit;

/**
 * Reads a recorded run into a {@link Run}: a trace written by {@code khepera-sim run --trace FILE} (or by a
 * test), or a run recording folder saved from the window (its {@code start.arena}, {@code run.edits},
 * {@code run.settings} and {@code run.trace}). The arena, controllers, seed and settings come from the
 * recording the way {@code khepera-sim verify} takes them, so {@link Run#rerun()} makes the same run again.
 */
final class RecordedRuns {
    /** Largest trace read, bytes (a one-hour trace at 50 ms is about 11 MB a robot). */
    private static final long MAX_TRACE_BYTES = 256L << 20;

    private RecordedRuns() {
    }

    /**
     * @param path a trace file or a run recording folder
     * @param arenaFile the arena it was recorded in, or null to find it as {@code verify} does
     * @return the run as recorded
     */
    static Run load(Path path, Path arenaFile) {
        boolean folder = Files.isDirectory(path);
        Path traceFile = folder ? path.resolve("run.trace") : path;
        if (!Files.isRegularFile(traceFile)) {
            throw new IllegalArgumentException(folder ? "the run recording " + path + " has no run.trace; save the"
                    + " recording from the window (it keeps the run's trace), or give a trace file"
                    : "no trace file " + path + "; give a trace written by 'khepera-sim run --trace FILE' or a run"
                    + " recording folder");
        }
        String text = TestKit.readTrace(traceFile, MAX_TRACE_BYTES);
        TraceSamples samples = TraceSamples.parse(text, traceFile.toString());
        Map<String, String> h = samples.header;
        if (samples.robots.isEmpty()) {
            throw TestKit.traceError(traceFile.toString(), 0, "the trace has no sample; it ends before its first"
                    + " sample line");
        }
        KitArena arena = arena(path, traceFile, folder, arenaFile, h.get("arena"));
        KitEdits edits = folder && Files.isRegularFile(path.resolve("run.edits"))
                ? KitEdits.load(path.resolve("run.edits")) : null;
        KitSettings base = folder && Files.isRegularFile(path.resolve("run.settings"))
                ? KitSettings.load(path.resolve("run.settings")) : settings(h.get("settings"));
        int n = samples.robots.size();
        List<String> controllers = new ArrayList<>();
        List<KitSettings> settings = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            String own = h.get("robot-" + i);
            String[] parts = own == null ? null : own.split(" settings ", 2);
            controllers.add(parts == null ? h.get("controller") : parts[0]);
            settings.add(parts == null ? base : settings(parts.length > 1 ? parts[1] : "defaults"));
        }
        TraceSamples.Series first = samples.robots.get(0);
        double seconds = first.nanos[first.size - 1] / 1e9;
        String arenaArg = arenaFile != null ? arenaFile.toString() : folder
                ? path.resolve("start.arena").toString() : arena.name();
        RunSpec spec = new RunSpec(arenaArg, arena, controllers, settings, List.of(), Long.parseLong(h.get("seed")),
                seconds, Long.parseLong(h.get("sample-ms")), false, RunSpec.DEFAULT_HANG_TIMEOUT, edits);
        return shape(spec, samples, text, traceFile, edits);
    }

    private static Run shape(RunSpec spec, TraceSamples samples, String text, Path traceFile, KitEdits edits) {
        KitArena arena = spec.arena();
        LongFunction<KitArena> arenaAt = t -> edits == null ? arena : edits.arenaAt(arena, t);
        // A trace has no events: its contacts are those its samples saw (see RecordedContacts).
        RecordedContacts finder = new RecordedContacts(samples, arenaAt);
        int n = samples.robots.size();
        List<RobotRun> robots = new ArrayList<>();
        Map<String, Double> enteredByAny = new LinkedHashMap<>();
        Ending unknown = new Ending(Ending.Kind.NOT_RECORDED, Optional.empty(), "", Optional.empty());
        for (int i = 0; i < n; i++) {
            TraceSamples.Series s = samples.robots.get(i);
            String cls = spec.controllers().get(i);
            String simple = cls.substring(cls.lastIndexOf('.') + 1);
            Map<String, SimTime> entered = RunShapes.regionsEntered(s, arena);
            entered.forEach((r, t) -> enteredByAny.merge(r, t.seconds(), StrictMath::min));
            robots.add(new RobotRun(i, n == 1 ? simple : simple + "#" + i, cls, RunShapes.path(s), finder.contacts(i),
                    entered, unknown, RunShapes.pathLength(s), -1, Double.NaN));
        }
        List<Cap> caps = RunShapes.caps(samples, arena);
        Map<String, Integer> capsIn = new LinkedHashMap<>();
        for (KitRegion r : arena.regions()) {
            capsIn.put(r.name(),
                    (int) caps.stream().filter(c -> c.heldAtEnd() < 0 && r.contains(c.endX(), c.endY())).count());
        }
        Score score = withoutCoverage(RunShapes.score(TestKit.score(arena, spec.seconds(), enteredByAny, capsIn)),
                arena);
        return new Run(spec, traceFile, SimTime.ofSeconds(spec.seconds()), robots, caps, score, text, List.of());
    }

    /**
     * A trace does not record the floor a robot covered: its {@code cover} tasks say so rather than score 0 silently.
     */
    private static Score withoutCoverage(Score s, KitArena arena) {
        List<TaskScore> tasks = new ArrayList<>();
        for (int i = 0; i < s.tasks().size(); i++) {
            TaskScore t = s.tasks().get(i);
            tasks.add(arena.isCoverTask(i) ? new TaskScore(t.task(), 0, 0, t.max(),
                    "not known from a trace (the floor covered is not recorded; rerun() the run for it)") : t);
        }
        return new Score(tasks, tasks.stream().mapToDouble(TaskScore::points).sum(), s.max());
    }

    /**
     * The recorded arena: given, the recording's start.arena, an arena file beside the trace, or the bundled one it
     * names.
     */
    private static KitArena arena(Path path, Path traceFile, boolean folder, Path arenaFile, String recorded) {
        String[] nameAndSha = recorded.split(" sha256=", 2);
        String sha = nameAndSha.length == 2 ? nameAndSha[1] : null;
        KitArena a;
        if (arenaFile != null) {
            a = TestKit.arenaFile(arenaFile);
        } else if (folder && Files.isRegularFile(path.resolve("start.arena"))) {
            a = TestKit.arenaFormatFile(path.resolve("start.arena"));
        } else {
            Optional<KitArena> beside = TestKit.arenaBeside(traceFile, nameAndSha[0], sha);
            if (beside.isPresent()) {
                a = beside.get();
            } else if (TestKit.bundledArenas().contains(nameAndSha[0])) {
                a = TestKit.bundledArena(nameAndSha[0]);
            } else {
                throw new IllegalArgumentException("the arena '" + nameAndSha[0] + "' of " + traceFile
                        + " is not bundled"
                        + " and no " + nameAndSha[0] + ".arena or start.arena with its SHA-256 lies beside the trace;"
                        + " give it: Run.load(trace, Path.of(\"" + nameAndSha[0] + ".arena\"))");
            }
        }
        if (sha != null && !a.sha256().equals(sha)) {
            throw new IllegalArgumentException("the arena " + a.name() + " is not the one " + traceFile
                    + " was recorded in"
                    + " (its SHA-256 is " + a.sha256() + ", the trace names " + sha + "); give the recorded"
                    + " one: Run.load(trace, arenaFile)");
        }
        return a;
    }

    /** @return the settings a trace's header describes: {@code defaults}, or {@code key=value} pairs */
    static KitSettings settings(String described) {
        KitSettings s = KitSettings.defaults();
        if (described == null || described.isBlank() || described.equals("defaults")) {
            return s;
        }
        for (String assignment : described.trim().split(" ")) {
            s = s.with(assignment);
        }
        return s;
    }
}
