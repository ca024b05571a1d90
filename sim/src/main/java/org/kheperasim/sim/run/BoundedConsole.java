package org.kheperasim.sim.run;

import java.util.ArrayDeque;
import java.util.Locale;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ConsoleSink;

/**
 * A run's console with a budget: lines pass until their text reaches the limit, then are counted and
 * dropped, so a controller that prints without end (10 KB every simulated millisecond is 6 GB in a
 * 600 s run) costs neither the disk nor the grader's memory. The last few error lines past the limit
 * are kept and shown at the end, since the simulator's own report of a controller's fault (it threw,
 * hung, broke a rule) comes last, when the controller is stopped; then one line says what was
 * dropped.
 */
public final class BoundedConsole implements ConsoleSink {
    /** Error lines kept past the limit, the latest ones. */
    private static final int KEPT_ERRORS = 8;

    private final ConsoleSink out;
    private final long limit;
    private long used;
    private long droppedLines;
    private long droppedChars;
    private long lastTime;
    private final ArrayDeque<ConsoleLine> lastErrors = new ArrayDeque<>();

    /**
     * @param out   where the lines go
     * @param limit characters of line text let through, at most
     */
    BoundedConsole(ConsoleSink out, long limit) {
        this.out = out;
        this.limit = limit;
    }

    @Override
    public synchronized void accept(ConsoleLine line) {
        lastTime = StrictMath.max(lastTime, line.timeNanos());
        int size = line.text().length() + 1;
        if (used + size <= limit) {
            used += size;
            out.accept(line);
            return;
        }
        used = limit; // once over, stay over: no later short line slips through out of order
        if (line.kind() == ConsoleLine.Kind.ERROR) {
            lastErrors.addLast(line);
            if (lastErrors.size() > KEPT_ERRORS) {
                count(lastErrors.removeFirst());
            }
        } else {
            count(line);
        }
    }

    private void count(ConsoleLine line) {
        droppedLines++;
        droppedChars += line.text().length() + 1;
    }

    /** At the run's end: the kept error lines, then what was dropped (last, so that a tail of the output holds it). */
    synchronized void finish() {
        int kept = lastErrors.size();
        while (!lastErrors.isEmpty()) {
            out.accept(lastErrors.removeFirst());
        }
        if (droppedLines > 0) {
            out.accept(new ConsoleLine(lastTime, "khepera-sim", ConsoleLine.Kind.INFO, note(droppedLines, droppedChars, limit)
                    + (kept == 0 ? "" : "; the last " + kept + " error lines past it are above")));
        }
    }

    /** @return the note on what was dropped; the grader reads it back ({@code OUTPUT_DROPPED}) */
    static String note(long lines, long chars, long limit) {
        return String.format(Locale.ROOT, "%s %d lines (%s) of controller output over the run's limit of %s",
                OUTPUT_DROPPED, lines, size(chars), size(limit));
    }

    /** How the note begins, for a reader of the console's text (the grader). */
    public static final String OUTPUT_DROPPED = "dropped";

    static String size(long chars) {
        if (chars < 10_000) {
            return chars + " characters";
        }
        return chars < 10_000_000 ? String.format(Locale.ROOT, "%.0f KB", chars / 1e3)
                : String.format(Locale.ROOT, "%.0f MB", chars / 1e6);
    }
}
