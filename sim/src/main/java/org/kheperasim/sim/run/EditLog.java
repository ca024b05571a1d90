package org.kheperasim.sim.run;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.ArenaFormatException;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.files.AtomicFiles;
import org.kheperasim.sim.files.TextFiles;

/**
 * The arena edits made during a run, each stamped with the simulated time it took effect at, so
 * that a run with edits replays exactly ({@link Simulation.Builder#edits}). Thread-safe: the
 * session's thread appends, the window reads.
 *
 * <p>As text (a sidecar file next to the trace, {@code run.edits}):
 * <pre>
 * khepera-edits 1
 * &#64; 1234000000
 * khepera-arena 1
 * ...the edited arena in canonical form...
 * end
 * </pre>
 * A stamp is a whole number of nanoseconds of simulated time: not negative, on the engine's 1 ms
 * tick grid (edits happen between ticks), in time order. Whether every stamp lies within a run is
 * checked when the run is known ({@link #checkWithin}). A file holds at most {@link #MAX_EDITS}
 * edits and {@link #MAX_FILE_BYTES} bytes.
 */
public final class EditLog {
    /** The first line of an edit log file. */
    public static final String HEADER = "khepera-edits 1";
    /** Most edits in one log. */
    public static final int MAX_EDITS = 10_000;
    /** Largest edit log file, bytes. */
    public static final long MAX_FILE_BYTES = 64L << 20;

    /**
     * @param timeNanos simulated time the edit took effect at, ns (a tick boundary)
     * @param arena the arena from then on
     */
    public record Edit(long timeNanos, Arena arena) {
    }

    private final String source;
    private final List<Edit> edits = new ArrayList<>();
    /** The line of each edit's stamp in {@link #source}; 0 for edits recorded in this process. */
    private final List<Integer> lines = new ArrayList<>();

    /** An empty log, to record a run's edits in. */
    public EditLog() {
        this("the recorded edits");
    }

    private EditLog(String source) {
        this.source = source;
    }

    /**
     * Record an edit.
     *
     * @param timeNanos when, simulated ns: not negative, a whole number of ticks, not before the last edit
     * @param arena the arena from then on
     * @throws IllegalArgumentException naming the stamp and what is wrong with it
     */
    public synchronized void add(long timeNanos, Arena arena) {
        String problem = stampProblem(timeNanos);
        if (problem != null) {
            throw new IllegalArgumentException(problem);
        }
        add(timeNanos, arena, 0);
    }

    private void add(long timeNanos, Arena arena, int line) {
        if (!edits.isEmpty() && edits.get(edits.size() - 1).timeNanos() > timeNanos) {
            throw new IllegalArgumentException("edit at " + seconds(timeNanos) + " comes before the edit at "
                    + seconds(edits.get(edits.size() - 1).timeNanos()) + "; edits must be in time order");
        }
        edits.add(new Edit(timeNanos, arena));
        lines.add(line);
    }

    /** @return the edits in time order */
    public synchronized List<Edit> edits() {
        return List.copyOf(edits);
    }

    /** @return how many edits */
    public synchronized int size() {
        return edits.size();
    }

    /**
     * Checks that every edit falls within a run that ends at {@code endNanos}: an edit after the
     * end would silently never happen.
     *
     * @param endNanos when the run ends, simulated ns
     * @throws EditLogException naming the first edit's line, its time, the run's end and the fix
     */
    public synchronized void checkWithin(long endNanos) {
        for (int i = 0; i < edits.size(); i++) {
            long t = edits.get(i).timeNanos();
            if (t > endNanos) {
                throw new EditLogException(source, lines.get(i), "the edit at " + seconds(t)
                        + " comes after the end of the run at " + seconds(endNanos)
                        + "; run at least that long (--seconds "
                        + String.format(Locale.ROOT, "%.3f", t / 1e9) + ") or remove the edit");
            }
        }
    }

    /** @return the log as text */
    public synchronized String write() {
        StringBuilder sb = new StringBuilder(HEADER).append('\n');
        for (Edit e : edits) {
            sb.append("@ ").append(e.timeNanos()).append('\n').append(ArenaFormat.write(e.arena())).append("end\n");
        }
        return sb.toString();
    }

    /**
     * @param text an edit log's text
     * @param source how errors name it
     * @return the log
     * @throws EditLogException naming {@code source:line}, what is wrong and the fix
     */
    public static EditLog parse(String text, String source) {
        String[] lines = text.split("\n", -1);
        String first = lines[0].startsWith("\uFEFF") ? lines[0].substring(1) : lines[0];
        if (!first.strip().equals(HEADER)) {
            throw new EditLogException(source, 1, "expected '" + HEADER + "' as the first line; is this an edit log"
                    + " saved by the simulator (run.edits)?");
        }
        EditLog log = new EditLog(source);
        int i = 1;
        while (i < lines.length) {
            String line = lines[i].strip();
            if (line.isEmpty()) {
                i++;
                continue;
            }
            int stampLine = i + 1;
            if (!line.startsWith("@ ")) {
                throw new EditLogException(source, stampLine, "expected '@ <simulated ns>', found '" + shorten(line)
                        + "'; each edit starts with its time, e.g. '@ 12000000' for 12 ms");
            }
            if (log.edits.size() >= MAX_EDITS) {
                throw new EditLogException(source, stampLine, "more than " + MAX_EDITS
                        + " edits; an edit log may hold at most that many, remove edits from here on");
            }
            long t = stamp(source, stampLine, line.substring(2).strip());
            int start = ++i;
            StringBuilder arena = new StringBuilder();
            while (i < lines.length && !lines[i].strip().equals("end")) {
                arena.append(lines[i]).append('\n');
                i++;
            }
            if (i >= lines.length) {
                throw new EditLogException(source, stampLine, "the edit has no closing 'end' line; end each edit's"
                        + " arena with a line 'end'");
            }
            i++;
            Arena a;
            try {
                a = ArenaFormat.parse(arena.toString(), source);
            } catch (ArenaFormatException e) {
                throw new EditLogException(source, start + Math.max(1, e.line()), "in the arena of the edit at line "
                        + stampLine + ": " + e.what());
            }
            try {
                log.add(t, a, stampLine);
            } catch (IllegalArgumentException e) {
                throw new EditLogException(source, stampLine, e.getMessage());
            }
        }
        return log;
    }

    private static long stamp(String source, int line, String digits) {
        if (digits.isEmpty() || digits.length() > 19 || !digits.chars().allMatch(c -> c >= '0' && c <= '9')) {
            throw new EditLogException(source, line, "'@ " + shorten(digits) + "' needs a whole, non-negative number"
                    + " of simulated ns, e.g. '@ 12000000' for 12 ms");
        }
        long t;
        try {
            t = Long.parseLong(digits);
        } catch (NumberFormatException e) {
            throw new EditLogException(source, line, "'@ " + digits + "' is too large a time; give simulated ns"
                    + " below " + Long.MAX_VALUE);
        }
        String problem = stampProblem(t);
        if (problem != null) {
            throw new EditLogException(source, line, problem);
        }
        return t;
    }

    /** @return what is wrong with a stamp, or null */
    private static String stampProblem(long timeNanos) {
        if (timeNanos < 0) {
            return "edit time " + timeNanos + " ns is negative; a run starts at 0";
        }
        if (timeNanos % Engine.TICK_NANOS != 0) {
            long below = timeNanos - timeNanos % Engine.TICK_NANOS;
            return "edit time " + timeNanos + " ns is not on the engine's " + Engine.TICK_NANOS / 1_000_000
                    + " ms tick grid (edits happen between ticks); give a multiple of " + Engine.TICK_NANOS
                    + " ns, e.g. " + below + " or " + (below + Engine.TICK_NANOS);
        }
        return null;
    }

    /** @param file where to save it, atomically ({@link AtomicFiles}) */
    public void save(Path file) {
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            AtomicFiles.write(file, write());
        } catch (IOException e) {
            throw new UncheckedIOException("cannot save the edit log " + file + ": " + e.getMessage(), e);
        }
    }

    /**
     * @param file an edit log file
     * @return the log
     * @throws EditLogException naming the file and line at fault
     * @throws UncheckedIOException when the file cannot be read
     */
    public static EditLog load(Path file) {
        String source = file.toString();
        return parse(TextFiles.readUtf8(file, MAX_FILE_BYTES, "edit log",
                (line, what) -> new EditLogException(source, line, what)), source);
    }

    private static String seconds(long nanos) {
        return String.format(Locale.ROOT, "%.3f s (%d ns)", nanos / 1e9, nanos);
    }

    private static String shorten(String s) {
        return s.length() <= 40 ? s : s.substring(0, 37) + "...";
    }
}
