package org.kheperasim.sim.replay;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFiles;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.edit.ArenaEdits;
import org.kheperasim.sim.files.TextFiles;
import org.kheperasim.sim.run.EditLog;
import org.kheperasim.sim.trace.TraceFormatException;

/**
 * Opens what can be replayed, recognised by its content: a run recording folder (the window's
 * "Save run recording": {@code start.arena}, {@code run.edits}, {@code run.trace}), a trace file
 * ({@code run --trace}; its arena is the {@code start.arena} or the arena file of the same name
 * beside it, or the bundled arena it names), or a robot-link recording of a real robot (drawn in an empty 4 × 4 ft
 * arena).
 */
public final class ReplayFiles {
    /**
     * Largest file read, bytes: {@code verify}'s limit (a one-hour trace at 50 ms is about 11 MB a robot, so
     * this is some 20 robot-hours); the whole file is held in memory, twice while it is decoded.
     */
    public static final long MAX_FILE_BYTES = 256L << 20;

    private ReplayFiles() {
    }

    /**
     * @param path a recording folder, a trace or a robot-link recording
     * @return the run, ready to watch
     * @throws org.kheperasim.sim.files.InputFileException naming the file and line at fault
     * @throws java.io.UncheckedIOException when a file cannot be read
     */
    public static Replay open(Path path) {
        List<String> notes = new ArrayList<>();
        if (Files.isDirectory(path)) {
            return recording(path, notes);
        }
        String text = read(path);
        String source = path.toString();
        if (text.startsWith(LinkRecordingReader.MAGIC)) {
            Arena arena = ArenaEdits.blank("robot-link", 1219.2, 1219.2);
            RobotSeries s = LinkRecordingReader.read(text, source, 609.6, 609.6, 90, notes);
            notes.add(source + ": a real robot's run; its path is worked out from the encoders from the middle of an"
                    + " empty arena, so it drifts as odometry does");
            return new Replay(Replay.Kind.LINK_RECORDING, source, arena, List.of(), List.of(s), null, notes);
        }
        Arena arena = traceArena(path, text, notes);
        TraceReplayReader.Result r = TraceReplayReader.read(text, source, arena, notes);
        return new Replay(Replay.Kind.TRACE, source, arena, List.of(), r.robots(), r.caps(), notes);
    }

    /**
     * A real run and its simulation on one page ({@code compare}): two robot-link recordings played
     * side by side in the arena, robot 1 the real robot and robot 2 its simulation, each one's path
     * worked out from its own encoders from the same start (as {@code compare} compares them).
     *
     * @param real the real run's recording (its text)
     * @param simulated the simulation, as a recording
     * @param source what the page names as made from
     * @param arena the arena the run took place in
     * @param start where both started
     * @param mmPerPulse the robot's wheel travel per encoder pulse, mm (its type's or its calibration's)
     * @param wheelBaseMm its wheel base, mm
     * @return the two runs, to play
     * @throws org.kheperasim.sim.files.InputFileException naming the recording and line at fault
     */
    public static Replay sideBySide(String real, String simulated, String source, Arena arena,
            org.kheperasim.sim.arena.Pose start, double mmPerPulse, double wheelBaseMm) {
        List<String> notes = new ArrayList<>();
        RobotSeries r = LinkRecordingReader.read(real, source, start.x(), start.y(), start.headingDeg(), mmPerPulse,
                wheelBaseMm, notes);
        RobotSeries s = LinkRecordingReader.read(simulated, source + " (simulated)", start.x(), start.y(),
                start.headingDeg(), mmPerPulse, wheelBaseMm, notes);
        notes.add("robot 1 is the real robot, robot 2 its simulation; both paths are worked out from their encoders"
                + " from the same start, so the real one drifts as odometry does");
        return new Replay(Replay.Kind.LINK_RECORDING, source, arena, List.of(), List.of(r, s), null, notes);
    }

    /**
     * A trace whose arena the caller already has (grade's traces lie apart from their arena files).
     *
     * @param trace a trace file
     * @param arena the arena it was recorded in
     * @return the run, ready to watch
     * @throws org.kheperasim.sim.files.InputFileException naming the file and line at fault
     * @throws java.io.UncheckedIOException when the file cannot be read
     */
    public static Replay open(Path trace, Arena arena) {
        List<String> notes = new ArrayList<>();
        TraceReplayReader.Result r = TraceReplayReader.read(read(trace), trace.toString(), arena, notes);
        return new Replay(Replay.Kind.TRACE, trace.toString(), arena, List.of(), r.robots(), r.caps(), notes);
    }

    private static Replay recording(Path dir, List<String> notes) {
        Path start = dir.resolve("start.arena");
        Path trace = dir.resolve("run.trace");
        if (!Files.isRegularFile(start) || !Files.isRegularFile(trace)) {
            throw new TraceFormatException(dir.toString(), 0, "a run recording folder holds start.arena and run.trace;"
                    + (Files.isRegularFile(start) ? " run.trace is missing (recordings saved before this version have"
                    + " none: replay them with 'run' as replay.txt says, adding --trace"
                    + " run.trace)" : " start.arena is missing"));
        }
        Arena arena = ArenaFormat.load(start);
        Path editsFile = dir.resolve("run.edits");
        List<EditLog.Edit> edits = Files.isRegularFile(editsFile) ? EditLog.load(editsFile).edits() : List.of();
        TraceReplayReader.Result r = TraceReplayReader.read(read(trace), trace.toString(), arena, notes);
        return new Replay(Replay.Kind.RECORDING, dir.toString(), arena, edits, r.robots(), r.caps(), notes);
    }

    /**
     * The arena of a bare trace: an arena file beside it ({@link #arenaBeside}), else the bundled arena its header
     * names.
     */
    private static Arena traceArena(Path trace, String text, List<String> notes) {
        String name = null;
        String sha = null;
        for (String line : text.lines().limit(40).toList()) {
            if (line.startsWith("# arena ")) {
                String[] f = line.substring(8).split(" ");
                name = f[0];
                sha = f.length > 1 && f[1].startsWith("sha256=") ? f[1].substring(7) : null;
            }
        }
        Beside beside = arenaBeside(trace, name, sha);
        if (beside != null) {
            notes.add(trace + ": arena " + beside.file().getFileName() + " beside it");
            return beside.arena();
        }
        if (name != null && ArenaFormat.bundledNames().contains(name)) {
            Arena a = ArenaFormat.loadBundled(name);
            if (sha != null && !sha.equals(ArenaFormat.sha256(a))) {
                notes.add(trace + ": the run used an arena named '" + name + "' that differs from the bundled one;"
                        + " the walls drawn may not be the run's (put its arena file beside the trace)");
            } else {
                notes.add(trace + ": arena '" + name + "' (bundled)");
            }
            return a;
        }
        notes.add(trace + ": its arena '" + name + "' is not bundled and neither start.arena nor " + name
                + ".arena (the same arena) lies beside it; drawing the path in an empty 4 x 4 ft arena");
        return ArenaEdits.blank("unknown", 1219.2, 1219.2);
    }

    /**
     * The arena file a trace was recorded in, found beside it: {@code start.arena} (a recording's
     * copy), else {@code NAME.arena} for the arena the trace names, either only when its SHA-256 is
     * the one the trace records (or the trace records none).
     *
     * @param trace the trace file
     * @param name the arena's name in the trace's header, or null
     * @param sha256 the arena's SHA-256 in the header, or null
     * @return the file and its arena, or null when none lies beside the trace
     */
    public static Beside arenaBeside(Path trace, String name, String sha256) {
        Path parent = trace.toAbsolutePath().getParent();
        if (parent == null) {
            return null;
        }
        Beside start = recorded(parent.resolve("start.arena"), sha256);
        if (start != null || name == null || !name.matches("[A-Za-z0-9._-]+")) {
            return start;
        }
        return recorded(parent.resolve(name + ArenaFormat.EXTENSION), sha256);
    }

    /**
     * An arena file found beside a trace, and the arena read from it.
     *
     * @param file the file
     * @param arena its arena
     */
    public record Beside(Path file, Arena arena) {
    }

    /**
     * @return {@code file} and its arena when it is a readable arena whose SHA-256 is {@code sha256} (any, when null),
     *     else null
     */
    private static Beside recorded(Path file, String sha256) {
        if (!Files.isRegularFile(file)) {
            return null;
        }
        try {
            Arena a = ArenaFiles.load(file);
            return sha256 == null || sha256.equals(ArenaFormat.sha256(a)) ? new Beside(file, a) : null;
        } catch (RuntimeException e) {
            return null;   // not a readable arena: as if none lay there
        }
    }

    private static String read(Path file) {
        return TextFiles.readUtf8(file, MAX_FILE_BYTES, "replay",
                (line, what) -> new TraceFormatException(file.toString(), line, what));
    }
}
