package org.kheperasim.sim.cli;

import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFiles;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.files.TextFiles;
import org.kheperasim.sim.replay.ReplayFiles;
import org.kheperasim.sim.run.EditLog;
import org.kheperasim.sim.run.RunRecording;
import org.kheperasim.sim.run.SettingsFile;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.trace.TraceDiff;
import org.kheperasim.sim.trace.TraceFormatException;
import org.kheperasim.sim.trace.TraceReader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code verify}: runs a recorded run again from what its trace (or run recording) names (arena,
 * controllers, seed, settings, edits) and says whether it comes out identical, or names the first
 * sample that differs and how.
 */
@Command(name = "verify", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Run a recorded run again and compare: 'identical', or the first sample that differs.",
            "RECORDING is a trace file (run --trace) or a run recording folder (with its run.trace)."},
        footer = "Exit status: 0 identical; 1 it differs; 2 bad input (an option, a file, a name the tool cannot use).")
final class VerifyCommand implements Callable<Integer> {
    private static final long MAX_TRACE_BYTES = ReplayFiles.MAX_FILE_BYTES;

    @Parameters(index = "0", paramLabel = "RECORDING|TRACE", description = "a trace file, or a run recording folder")
    Path recording;

    @Option(names = "--arena", paramLabel = "FILE",
            description = "the arena the trace was recorded in (default: start.arena in a recording or beside the"
                    + " trace, the arena file of the same name beside it, or the bundled arena it names)")
    Path arenaFile;

    @Option(names = "--classpath", paramLabel = "PATHS", split = "${sys:path.separator}",
            description = "where the recorded controller's classes are (default: a recording's own, as its replay.txt"
                    + " names them; not needed for a bundled controller)")
    List<Path> classpath = new ArrayList<>();

    @Override
    public Integer call() {
        boolean folder = Files.isDirectory(recording);
        Path traceFile = folder ? recording.resolve("run.trace") : recording;
        if (!Files.exists(traceFile)) {
            throw new IllegalArgumentException(folder
                    ? "the run recording " + recording + " has no run.trace to compare"
                    + " with; save the recording from the window (it keeps the run's trace), or verify a trace file"
                    : "no trace file " + recording
                    + "; give a trace written by 'run --trace FILE' or a run recording folder");
        }
        String recorded = TextFiles.readUtf8(traceFile, MAX_TRACE_BYTES, "trace",
                (line, what) -> new TraceFormatException(traceFile.toString(), line, what));
        TraceReader.Summary summary = TraceReader.parse(recorded, traceFile.toString());
        Map<String, String> h = summary.header();
        Arena arena = arena(folder, h.get("arena"));
        // A recording's own settings file is what it replays with (the trace's header says what it ran with).
        Settings settings = folder && Files.isRegularFile(recording.resolve("run.settings"))
                ? SettingsFile.load(recording.resolve("run.settings")) : settings(h.get("settings"));
        Simulation.Builder run = Simulation.builder().arena(arena).controller(h.get("controller"))
                .seed(whole(h, "seed", Long.MIN_VALUE)).settings(settings)
                .sampleMillis(whole(h, "sample-ms", 1)).seconds(summary.lastSeconds()).classpath(classpath(folder));
        for (int i = 0; h.containsKey("robot-" + i); i++) {
            String[] own = h.get("robot-" + i).split(" settings ", 2);
            run.robot(i, own[0], settings(own.length > 1 ? own[1] : "defaults"));
        }
        if (folder && Files.isRegularFile(recording.resolve("run.edits"))) {
            run.edits(EditLog.load(recording.resolve("run.edits")));
        }
        StringWriter again = new StringWriter();
        run.trace(again).console(line -> { }).run();
        TraceDiff.Result diff = TraceDiff.compare(recorded, again.toString());
        if (diff.identical()) {
            System.out.println("identical: " + diff.samples() + " sample lines up to " + summary.lastSeconds()
                    + " s, " + traceFile);
            return ExitCodes.OK;
        }
        System.out.println("differs: " + traceFile);
        diff.header().forEach(line -> System.out.println("  header " + line));
        if (diff.firstSample() != null) {
            System.out.println("  first difference at " + diff.firstSample());
        } else {
            System.out.println("  every sample agrees");
        }
        return ExitCodes.FAILED;
    }

    /**
     * @return the classpath given, else a recording's own (its copy of the controller's classes, or
     *     what its replay.txt names): a recording of a controller compiled in the window verifies as it is
     */
    private List<Path> classpath(boolean folder) {
        if (!classpath.isEmpty() || !folder) {
            return classpath;
        }
        List<Path> own = RunRecording.classpath(recording);
        for (Path p : own) {
            if (!Files.exists(p)) {
                throw new IllegalArgumentException(
                        "the recording's replay.txt names the classpath entry " + p + ", which"
                        + " does not exist; give the controller's classes with --classpath DIR_OR_JAR");
            }
        }
        return own;
    }

    /**
     * The recorded arena: given, the recording's start.arena, the arena file beside the trace, or the bundled one the
     * trace names; its sha256 must match.
     */
    private Arena arena(boolean folder, String recordedArena) {
        String[] nameAndSha = recordedArena.split(" sha256=", 2);
        Arena a;
        if (arenaFile != null) {
            a = ArenaFiles.load(arenaFile, note -> { });
        } else if (folder && Files.isRegularFile(recording.resolve("start.arena"))) {
            a = ArenaFormat.load(recording.resolve("start.arena"));
        } else {
            ReplayFiles.Beside beside = folder ? null
                    : ReplayFiles.arenaBeside(recording, nameAndSha[0], nameAndSha.length == 2 ? nameAndSha[1] : null);
            a = beside != null ? beside.arena() : ArenaFormat.resolve(nameAndSha[0]);
        }
        if (nameAndSha.length == 2 && !ArenaFormat.sha256(a).equals(nameAndSha[1])) {
            throw new IllegalArgumentException("the arena " + a.name() + " is not the one recorded (its sha256 is "
                    + ArenaFormat.sha256(a) + ", the trace names " + nameAndSha[1]
                    + "); give the recorded one with --arena FILE");
        }
        return a;
    }

    /** @return the header's field as a whole number of at least {@code min}, or the trace's error naming it */
    private long whole(Map<String, String> header, String key, long min) {
        try {
            long v = Long.parseLong(header.get(key).strip());
            if (v >= min) {
                return v;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new TraceFormatException(recording.toString(), 0, "the header's " + key + " is '"
                + header.get(key) + "', not a whole number" + (min > 0 ? " of at least " + min : "") + "; is it a trace"
                + " written by run --trace?");
    }

    /** @return the settings a header describes: "defaults", or key=value pairs */
    private static Settings settings(String described) {
        Settings s = Settings.defaults();
        if (described == null || described.isBlank() || described.equals("defaults")) {
            return s;
        }
        for (String assignment : described.trim().split(" ")) {
            s = s.with(assignment);
        }
        return s;
    }
}
