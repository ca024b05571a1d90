package org.kheperasim.sim.trace;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Where two traces of the same run part: the header fields that differ, and the first sample line
 * that differs, named by its time, its robot (or cap) and the columns that changed.
 */
public final class TraceDiff {
    private static final String[] ROBOT_COLUMNS = ("t_s robot x_mm y_mm heading_deg speed_l speed_r enc_l enc_r contact"
            + " prox0 prox1 prox2 prox3 prox4 prox5 prox6 prox7 light0 light1 light2 light3 light4 light5 light6 light7"
            + " arm fingers object held_cap").split(" ");
    private static final String[] CAP_COLUMNS = "t_s cap id x_mm y_mm held_by".split(" ");

    /**
     * What differs.
     *
     * @param header one line per header field that differs, e.g. {@code settings: recorded defaults, now ...}
     * @param firstSample the first differing sample in words, or null when every sample agrees
     * @param samples how many sample lines the recorded trace has
     */
    public record Result(List<String> header, String firstSample, int samples) {
        /** @return true when both traces are the same, line for line */
        public boolean identical() {
            return header.isEmpty() && firstSample == null;
        }
    }

    private TraceDiff() {
    }

    /**
     * @param recorded the trace as recorded
     * @param now the trace of the run made again
     * @return where they part
     */
    public static Result compare(String recorded, String now) {
        List<String> a = recorded.lines().toList();
        List<String> b = now.lines().toList();
        List<String> header = new ArrayList<>();
        List<String> ha = a.stream().filter(TraceDiff::isHeader).toList();
        List<String> hb = b.stream().filter(TraceDiff::isHeader).toList();
        for (String line : ha) {
            String key = key(line);
            String other = hb.stream().filter(l -> key(l).equals(key)).findFirst().orElse(null);
            if (!line.equals(other)) {
                header.add(key + ": recorded '" + value(line) + "', now "
                        + (other == null ? "missing" : "'" + value(other) + "'"));
            }
        }
        List<String> sa = a.stream().filter(l -> !isHeader(l)).toList();
        List<String> sb = b.stream().filter(l -> !isHeader(l)).toList();
        String first = null;
        for (int i = 0; i < sa.size() && first == null; i++) {
            if (i >= sb.size()) {
                first = "the run made again ends before sample line " + (i + 1) + " ("
                        + sa.get(i).split(" ")[0] + " s)";
            } else if (!sa.get(i).equals(sb.get(i))) {
                first = describe(i + 1, sa.get(i), sb.get(i));
            }
        }
        if (first == null && sb.size() > sa.size()) {
            first = "the run made again has " + (sb.size() - sa.size())
                    + " more sample lines after the recorded ones end";
        }
        return new Result(header, first, sa.size());
    }

    /** A header line starts with {@code #}; a vision line does too, but it is a sample. */
    private static boolean isHeader(String line) {
        return line.startsWith("#") && !line.startsWith(TraceWriter.VISION_PREFIX);
    }

    private static String key(String headerLine) {
        String[] t = headerLine.split(" ", 3);
        return t.length > 1 ? t[1] : "";
    }

    private static String value(String headerLine) {
        String[] t = headerLine.split(" ", 3);
        return t.length > 2 ? t[2] : "";
    }

    private static String describe(int sample, String recorded, String now) {
        if (recorded.startsWith(TraceWriter.VISION_PREFIX) || now.startsWith(TraceWriter.VISION_PREFIX)) {
            String[] v = recorded.split(" ");
            return String.format(Locale.ROOT, "sample line %d: the vision turret's image%s differs (recorded '%s',"
                    + " now '%s')", sample, v.length > 4 ? " of robot " + v[3] + " at " + v[2] + " s" : "",
                    shorten(recorded), shorten(now));
        }
        String[] a = recorded.split(" ");
        String[] b = now.split(" ");
        boolean cap = a.length > 1 && a[1].equals("cap");
        String[] names = cap ? CAP_COLUMNS : ROBOT_COLUMNS;
        String who = cap ? "cap " + (a.length > 2 ? a[2] : "?") : "robot " + (a.length > 1 ? a[1] : "?");
        List<String> changes = new ArrayList<>();
        for (int k = 0; k < Math.max(a.length, b.length); k++) {
            String x = k < a.length ? a[k] : "(none)";
            String y = k < b.length ? b[k] : "(none)";
            if (!x.equals(y)) {
                changes.add((k < names.length ? names[k] : "column " + (k + 1)) + " recorded " + x + ", now " + y);
            }
        }
        String shown = String.join("; ", changes.subList(0, Math.min(3, changes.size())));
        return String.format(Locale.ROOT, "sample line %d (t = %s s, %s): %s%s", sample, a[0], who, shown,
                changes.size() > 3 ? "; and " + (changes.size() - 3) + " more columns" : "");
    }

    private static String shorten(String s) {
        return s.length() <= 60 ? s : s.substring(0, 57) + "...";
    }
}
