package org.kheperasim.sim.trace;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.engine.view.Contact;
import org.kheperasim.sim.files.TextFiles;

/**
 * Reads and checks a trace written by {@link TraceWriter}: the header, then every sample line,
 * each with the right number of well-formed columns and the times in order. What a script or a
 * test needs to trust a trace, e.g. one left by a run that was killed (whole lines only).
 */
public final class TraceReader {

    /** Largest trace read, bytes. */
    public static final long MAX_FILE_BYTES = 1L << 30;
    /** Header fields every trace has, after the format line. */
    public static final List<String> REQUIRED = List.of("seed", "arena", "controller", "settings", "sample-ms",
            "columns", "caps");

    private static final int ROBOT_COLUMNS = 30;
    private static final int CAP_COLUMNS = 6;
    /** The latest sample time, s: the longest run the command line makes ({@code run --seconds}). */
    private static final double MAX_SECONDS = 1e8;
    private static final Pattern TIME = Pattern.compile("\\d{1,12}\\.\\d{3}");
    private static final Pattern FIXED = Pattern.compile("-?\\d{1,12}\\.\\d{3}");
    private static final Pattern INT = Pattern.compile("-?\\d{1,10}");
    private static final Pattern GREY = Pattern.compile("\\d{1,3}");
    private static final Set<String> CONTACTS = names(Contact.values());
    private static final Set<String> FINGERS = names(GripperState.values());

    /**
     * What a trace holds.
     *
     * @param header      the header fields in order, e.g. {@code seed -> 42}
     * @param robotLines  how many robot sample lines
     * @param capLines    how many cap lines
     * @param lastSeconds the time of the last sample line, s (0 without samples)
     * @param visionLines how many vision lines (images a robot's vision turret gave its controller)
     */
    public record Summary(Map<String, String> header, int robotLines, int capLines, double lastSeconds,
            int visionLines) {
    }

    private TraceReader() {
    }

    /**
     * @param file a trace file
     * @return what it holds
     * @throws TraceFormatException naming the file and the line at fault
     * @throws java.io.UncheckedIOException when the file cannot be read
     */
    public static Summary read(Path file) {
        String source = file.toString();
        return parse(TextFiles.readUtf8(file, MAX_FILE_BYTES, "trace",
                (line, what) -> new TraceFormatException(source, line, what)), source);
    }

    /**
     * @param text   a trace's text
     * @param source how errors name it
     * @return what it holds
     * @throws TraceFormatException naming {@code source:line} and what is wrong
     */
    public static Summary parse(String text, String source) {
        if (!text.isEmpty() && !text.endsWith("\n")) {
            int last = (int) text.chars().filter(c -> c == '\n').count() + 1;
            throw new TraceFormatException(source, last, "the last line is not whole (no line end); the writer was"
                    + " stopped in the middle of a line (a run killed while it wrote): delete that line to read"
                    + " the rest");
        }
        String[] lines = text.split("\n", -1);
        String format = "# khepera-trace " + TraceWriter.FORMAT_VERSION;
        if (!lines[0].equals(format)) {
            throw new TraceFormatException(source, 1, "expected '" + format + "', found '" + shorten(lines[0])
                    + "'; is this a trace of this simulator's version?");
        }
        Map<String, String> header = new LinkedHashMap<>();
        int n = lines.length - 1;
        int i = 1;
        for (; i < n && lines[i].startsWith("#"); i++) {
            String field = lines[i].substring(1).strip();
            int space = field.indexOf(' ');
            String key = space < 0 ? field : field.substring(0, space);
            if (key.isEmpty() || header.putIfAbsent(key, space < 0 ? "" : field.substring(space + 1)) != null) {
                throw new TraceFormatException(source, i + 1,
                        "header field '" + shorten(key) + "' is empty or repeated");
            }
        }
        for (String key : REQUIRED) {
            if (!header.containsKey(key)) {
                throw new TraceFormatException(source, Math.min(i + 1, Math.max(1, n)), "the header has no '" + key
                        + "' field; a trace's header has " + String.join(", ", REQUIRED));
            }
        }
        int robots = 0;
        int caps = 0;
        int visions = 0;
        double last = 0;
        for (; i < n; i++) {
            if (lines[i].startsWith(TraceWriter.VISION_PREFIX)) {
                last = visionLine(source, i + 1, lines[i], last);
                visions++;
                continue;
            }
            String[] t = lines[i].split(" ", -1);
            double time = time(source, i + 1, t[0], last);
            if (t.length == CAP_COLUMNS && t[1].equals("cap")) {
                check(source, i + 1, t[2], INT, "cap id");
                check(source, i + 1, t[3], FIXED, "cap x");
                check(source, i + 1, t[4], FIXED, "cap y");
                check(source, i + 1, t[5], INT, "held_by");
                caps++;
            } else if (t.length == ROBOT_COLUMNS) {
                robotLine(source, i + 1, t);
                robots++;
            } else {
                throw new TraceFormatException(source, i + 1,
                        "a sample line has " + t.length + " columns; a robot line has "
                        + ROBOT_COLUMNS + " and a cap line " + CAP_COLUMNS + " (see the header's columns)");
            }
            last = time;
        }
        return new Summary(header, robots, caps, last, visions);
    }

    /** A vision line: the sample's time, the robot, when the image was taken, 64 grey levels 0..255. */
    private static double visionLine(String source, int line, String text, double previous) {
        String[] t = text.substring(TraceWriter.VISION_PREFIX.length()).split(" ", -1);
        if (t.length != 3 + VISION_PIXELS) {
            throw new TraceFormatException(source, line, "a vision line has " + t.length + " columns after '"
                    + TraceWriter.VISION_PREFIX.strip() + "'; it has t_s, robot, taken_s and "
                    + VISION_PIXELS + " pixels");
        }
        double time = time(source, line, t[0], previous);
        check(source, line, t[1], INT, "robot");
        check(source, line, t[2], FIXED, "taken_s");
        for (int c = 3; c < t.length; c++) {
            check(source, line, t[c], GREY, "pixel " + (c - 3));
            int grey = Integer.parseInt(t[c]);
            if (grey > 255) {
                throw new TraceFormatException(source, line,
                        "pixel " + (c - 3) + " is " + grey + "; a grey level is 0..255");
            }
        }
        return time;
    }

    private static final int VISION_PIXELS = 64;

    private static void robotLine(String source, int line, String[] t) {
        check(source, line, t[1], INT, "robot");
        for (int c = 2; c <= 4; c++) {
            check(source, line, t[c], FIXED, "x_mm y_mm heading_deg".split(" ")[c - 2]);
        }
        for (int c = 5; c <= 8; c++) {
            check(source, line, t[c], INT, "speed_l speed_r enc_l enc_r".split(" ")[c - 5]);
        }
        if (!CONTACTS.contains(t[9])) {
            throw new TraceFormatException(source, line,
                    "contact is '" + shorten(t[9]) + "'; expected one of " + CONTACTS);
        }
        for (int c = 10; c <= 26; c++) {
            check(source, line, t[c], INT, c <= 17 ? "prox" + (c - 10) : c <= 25 ? "light" + (c - 18) : "arm");
        }
        if (!FINGERS.contains(t[27])) {
            throw new TraceFormatException(source, line,
                    "fingers is '" + shorten(t[27]) + "'; expected one of " + FINGERS);
        }
        if (!t[28].equals("0") && !t[28].equals("1")) {
            throw new TraceFormatException(source, line, "object is '" + shorten(t[28]) + "'; expected 0 or 1");
        }
        check(source, line, t[29], INT, "held_cap");
    }

    private static double time(String source, int line, String token, double previous) {
        check(source, line, token, TIME, "t_s");
        double t = Double.parseDouble(token);
        if (t > MAX_SECONDS) {
            throw new TraceFormatException(source, line, "time " + token + " s is later than any run ends (at most "
                    + (long) MAX_SECONDS + " s); is it the right file?");
        }
        if (t < previous) {
            throw new TraceFormatException(source, line,
                    "time " + token + " s comes before the previous line's; a trace's"
                    + " lines are in time order");
        }
        return t;
    }

    private static void check(String source, int line, String token, Pattern form, String column) {
        if (!form.matcher(token).matches()) {
            throw new TraceFormatException(source, line, column + " is '" + shorten(token) + "'; expected "
                    + (form == INT ? "a whole number" : form == GREY
                            ? "a grey level, 0..255" : "a number with 3 decimals"));
        }
    }

    private static Set<String> names(Enum<?>[] values) {
        Set<String> names = new java.util.TreeSet<>();
        for (Enum<?> v : values) {
            names.add(v.name());
        }
        return Set.copyOf(names);
    }

    private static String shorten(String s) {
        return s.length() <= 40 ? s : s.substring(0, 37) + "...";
    }
}
