package org.kheperasim.sim.run;

import java.util.ArrayDeque;
import java.util.Locale;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ConsoleSink;

/**
 * A run's console with a budget: lines pass until their text reaches the limit, then are counted and
 * dropped, so a controller that prints without end (10 KB every simulated millisecond is 6 GB in a
 * 600 s run) costs neither the disk nor the grader's memory, nor time: a line past the limit is only
 * counted. The last few error lines past the limit are kept and shown at the end, since the
 * simulator's own report of a controller's fault (it threw, hung, broke a rule) comes last, when the
 * controller is stopped; then one line says how much was printed and how much kept. A fault message
 * is bounded like output ({@link #bounded}): an exception's message and stack trace of any size is
 * shown cut to a few KB, with the student's frames kept.
 */
public final class BoundedConsole implements ConsoleSink {
    /** How the note on what was dropped begins, for a reader of the console's text (the grader). */
    public static final String OUTPUT_DROPPED = "printed";
    /** Error lines kept past the limit, the latest ones. */
    private static final int KEPT_ERRORS = 8;
    /** The longest line of one line's text kept whole, characters (a print's line is cut there already). */
    static final int MAX_LINE = 8192;
    /** The most a text of several lines (a fault's message and stack trace) keeps, characters. */
    static final int MAX_TEXT = 16_384;
    /** Lines of such a text kept from its start; after them only stack frames and causes, up to {@link #MAX_LINES}. */
    private static final int HEAD_LINES = 40;
    private static final int MAX_LINES = 120;
    /** The longest line of such a text, characters. */
    private static final int MAX_PIECE = 2000;

    private final ConsoleSink out;
    private final long limit;
    private long used;
    /** Characters of line text passed on before the limit was reached. */
    private long shown;
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
            ConsoleLine passed = cut(line);
            used += passed.text().length() + 1;
            shown += passed.text().length() + 1;
            out.accept(passed);
            return;
        }
        used = limit; // once over, stay over: no later short line slips through out of order
        if (line.kind() == ConsoleLine.Kind.ERROR) {
            lastErrors.addLast(cut(line));
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

    private static ConsoleLine cut(ConsoleLine line) {
        String text = bounded(line.text());
        return text == line.text() ? line : new ConsoleLine(line.timeNanos(), line.source(), line.kind(), text);
    }

    /** At the run's end: the kept error lines, then what was dropped (last, so that a tail of the output holds it). */
    synchronized void finish() {
        int kept = lastErrors.size();
        long printed = shown + droppedChars;
        while (!lastErrors.isEmpty()) {
            ConsoleLine e = lastErrors.removeFirst();
            printed += e.text().length() + 1;
            out.accept(e);
        }
        if (droppedLines > 0) {
            out.accept(new ConsoleLine(lastTime, "khepera-sim", ConsoleLine.Kind.INFO,
                    note(droppedLines, printed, shown) + (kept == 0 ? "" : "; the last " + kept
                            + " error lines past it are above")));
        }
    }

    /**
     * @param lines   lines dropped
     * @param printed characters printed in all
     * @param kept    characters shown before the limit was reached
     * @return the note on what was printed and kept; the grader reads it back ({@link #OUTPUT_DROPPED})
     */
    static String note(long lines, long printed, long kept) {
        return String.format(Locale.ROOT, "%s %s of controller output; kept the first %s (the run's limit), dropped %d"
                + " lines", OUTPUT_DROPPED, size(printed), size(kept), lines);
    }

    static String size(long chars) {
        if (chars < 10_000) {
            return chars + " characters";
        }
        if (chars < 1_000_000) {
            return String.format(Locale.ROOT, "%.0f KB", chars / 1e3);
        }
        String mb = String.format(Locale.ROOT, chars < 10_000_000 ? "%.1f" : "%.0f", chars / 1e6);
        return (mb.endsWith(".0") ? mb.substring(0, mb.length() - 2) : mb) + " MB";
    }

    /**
     * A line's text bounded like output: one line of at most {@link #MAX_LINE} characters passes as it is; a
     * longer one, or a text of several lines (a fault's message with its stack trace), keeps its first
     * {@value #HEAD_LINES} lines, then only its stack frames and causes, each line at most {@value #MAX_PIECE}
     * characters, {@value #MAX_TEXT} characters in all, and says how much was cut.
     *
     * @param text a console line's text, or a controller's failure
     * @return it bounded (the same object when nothing was cut)
     */
    public static String bounded(String text) {
        if (text == null || (text.length() <= MAX_LINE && text.indexOf('\n') < 0)) {
            return text;
        }
        StringBuilder kept = new StringBuilder();
        int lines = 0;
        long cutLines = 0;
        long cutChars = 0;
        int from = 0;
        while (from <= text.length()) {
            int nl = text.indexOf('\n', from);
            int to = nl < 0 ? text.length() : nl;
            boolean frame = startsFrame(text, from, to);
            int length = to - from;
            if (kept.length() >= MAX_TEXT || lines >= MAX_LINES || (lines >= HEAD_LINES && !frame)) {
                cutLines++;
                cutChars += length + 1;
            } else {
                int piece = StrictMath.min(length, StrictMath.min(MAX_PIECE, MAX_TEXT - kept.length()));
                kept.append(lines > 0 ? "\n" : "").append(text, from, from + piece);
                if (piece < length) {
                    kept.append(" ...");
                    cutChars += length - piece;
                }
                lines++;
            }
            if (nl < 0) {
                break;
            }
            from = nl + 1;
        }
        if (cutLines > 0) {
            kept.append("\n... ").append(cutLines).append(" more lines");
        }
        if (cutChars > 0) {
            kept.append(" (").append(size(cutChars)).append(" cut)");
        }
        return kept.toString();
    }

    private static boolean startsFrame(String text, int from, int to) {
        int i = from;
        while (i < to && (text.charAt(i) == ' ' || text.charAt(i) == '\t')) {
            i++;
        }
        return text.startsWith("at ", i) || text.startsWith("Caused by: ", i) || text.startsWith("Suppressed: ", i)
                || text.startsWith("... ", i);
    }
}
