package org.kheperasim.sim.run;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;

/**
 * The arena edits made during a run, each stamped with the simulated time it took effect at, so
 * that a run with edits replays exactly ({@link Simulation.Builder#edits}). Thread-safe: the
 * session's thread appends, the window reads.
 *
 * <p>As text (a sidecar file next to the trace, {@code run.edits}):
 * <pre>
 * khepera-edits 1
 * @ 1234000000
 * khepera-arena 1
 * ...the edited arena in canonical form...
 * end
 * </pre>
 */
public final class EditLog {
    /** The first line of an edit log file. */
    public static final String HEADER = "khepera-edits 1";

    /**
     * @param timeNanos simulated time the edit took effect at, ns (a tick boundary)
     * @param arena the arena from then on
     */
    public record Edit(long timeNanos, Arena arena) {
    }

    private final List<Edit> edits = new ArrayList<>();

    /** @param timeNanos when @param arena the arena from then on */
    public synchronized void add(long timeNanos, Arena arena) {
        if (!edits.isEmpty() && edits.get(edits.size() - 1).timeNanos() > timeNanos) {
            throw new IllegalArgumentException("edits must be recorded in time order");
        }
        edits.add(new Edit(timeNanos, arena));
    }

    /** @return the edits in time order */
    public synchronized List<Edit> edits() {
        return List.copyOf(edits);
    }

    /** @return how many edits */
    public synchronized int size() {
        return edits.size();
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
     * @throws IllegalArgumentException naming the line at fault
     */
    public static EditLog parse(String text, String source) {
        String[] lines = text.split("\n", -1);
        if (lines.length == 0 || !lines[0].strip().equals(HEADER)) {
            throw new IllegalArgumentException(source + ":1: expected '" + HEADER + "' as the first line");
        }
        EditLog log = new EditLog();
        int i = 1;
        while (i < lines.length) {
            String line = lines[i].strip();
            if (line.isEmpty()) {
                i++;
                continue;
            }
            if (!line.startsWith("@ ")) {
                throw new IllegalArgumentException(source + ":" + (i + 1) + ": expected '@ <simulated ns>', found '" + line + "'");
            }
            long t;
            try {
                t = Long.parseLong(line.substring(2).strip());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(source + ":" + (i + 1) + ": '" + line + "' needs a whole number of ns");
            }
            int start = ++i;
            StringBuilder arena = new StringBuilder();
            while (i < lines.length && !lines[i].strip().equals("end")) {
                arena.append(lines[i]).append('\n');
                i++;
            }
            if (i >= lines.length) {
                throw new IllegalArgumentException(source + ":" + start + ": the edit has no closing 'end' line");
            }
            i++;
            log.add(t, ArenaFormat.parse(arena.toString(), source + " (edit at line " + start + ")"));
        }
        return log;
    }

    /** @param file where to save it, atomically */
    public void save(Path file) {
        try {
            Path parent = file.toAbsolutePath().getParent();
            Files.createDirectories(parent);
            Path temp = Files.createTempFile(parent, file.getFileName().toString(), ".part");
            Files.writeString(temp, write(), StandardCharsets.UTF_8);
            try {
                Files.move(temp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } catch (java.nio.file.AtomicMoveNotSupportedException e) {
                Files.move(temp, file, StandardCopyOption.REPLACE_EXISTING);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot save the edit log " + file + ": " + e.getMessage(), e);
        }
    }

    /** @param file an edit log file @return the log */
    public static EditLog load(Path file) {
        try {
            return parse(Files.readString(file, StandardCharsets.UTF_8), file.toString());
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the edit log " + file + ": " + e.getMessage(), e);
        }
    }
}
