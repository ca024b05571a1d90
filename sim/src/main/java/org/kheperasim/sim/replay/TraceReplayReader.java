package org.kheperasim.sim.replay;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.engine.view.Contact;
import org.kheperasim.sim.trace.TraceFormatException;
import org.kheperasim.sim.trace.TraceWriter;

/**
 * Reads the samples of a trace ({@link TraceWriter}'s format) into series, quickly (a one-hour
 * trace is some 70,000 lines). A trace whose writer died mid-line is read up to its last whole
 * line, and a last sample that not every robot reached is dropped; the reader says so in a note.
 */
final class TraceReplayReader {
    private static final int ROBOT_COLUMNS = 30;

    private TraceReplayReader() {
    }

    /**
     * @param text the trace
     * @param source how errors name it
     * @param arena the arena the run used (for the caps' radii)
     * @param notes where to say what was cut short
     * @return one series per robot, and the caps' moves
     * @throws TraceFormatException naming {@code source:line}
     */
    static Result read(String text, String source, Arena arena, List<String> notes) {
        String format = "# khepera-trace " + TraceWriter.FORMAT_VERSION;
        if (!text.startsWith(format + "\n")) {
            throw new TraceFormatException(source, 1, "expected '" + format + "' on the first line; is this a trace"
                    + " written by this simulator's 'run --trace' or a window's run recording?");
        }
        int end = text.length();
        if (!text.endsWith("\n")) {
            end = text.lastIndexOf('\n') + 1;
            notes.add(source + " ends in the middle of a line (its writer stopped); replaying what was written"
                    + " in whole lines");
        }
        double[] radii = new double[arena.caps().size()];
        for (int i = 0; i < radii.length; i++) {
            Cap c = arena.caps().get(i);
            radii[i] = c.radius();
        }
        CapTrack caps = new CapTrack(radii);
        List<RobotSeries> robots = new ArrayList<>();
        int[] channels = new int[RobotSeries.CHANNELS];
        String[] f = new String[ROBOT_COLUMNS];
        int lineNo = 0;
        int pos = 0;
        while (pos < end) {
            int nl = text.indexOf('\n', pos);
            String line = text.substring(pos, nl);
            pos = nl + 1;
            lineNo++;
            if (line.startsWith("#") || line.isEmpty()) {
                continue;
            }
            int n = split(line, f);
            try {
                if (n == 6 && f[1].equals("cap")) {
                    int id = Integer.parseInt(f[2]);
                    if (id < 0 || id >= 100_000) {
                        throw new TraceFormatException(source, lineNo, "cap id " + id + " is out of range");
                    }
                    caps.add(id, Double.parseDouble(f[0]), Double.parseDouble(f[3]), Double.parseDouble(f[4]),
                            Integer.parseInt(f[5]));
                    continue;
                }
                if (n != ROBOT_COLUMNS) {
                    throw new TraceFormatException(source, lineNo, "a sample line has " + ROBOT_COLUMNS
                            + " columns and a cap line 6; this one has " + n);
                }
                int id = Integer.parseInt(f[1]);
                if (id < 0 || id > robots.size()) {
                    throw new TraceFormatException(source, lineNo,
                            "robot " + id + " appears before robot " + robots.size());
                }
                if (id == robots.size()) {
                    robots.add(new RobotSeries());
                }
                for (int c = 0; c < 16; c++) {
                    channels[c] = Integer.parseInt(f[10 + c]);
                }
                channels[RobotSeries.SPEED] = Integer.parseInt(f[5]);
                channels[RobotSeries.SPEED + 1] = Integer.parseInt(f[6]);
                channels[RobotSeries.ENCODER] = Integer.parseInt(f[7]);
                channels[RobotSeries.ENCODER + 1] = Integer.parseInt(f[8]);
                robots.get(id).add(Double.parseDouble(f[0]), Double.parseDouble(f[2]), Double.parseDouble(f[3]),
                        Double.parseDouble(f[4]), channels, Contact.valueOf(f[9]), Integer.parseInt(f[26]),
                        GripperState.valueOf(f[27]), f[28].equals("1"), Integer.parseInt(f[29]));
            } catch (IllegalArgumentException e) {
                if (e instanceof TraceFormatException t) {
                    throw t;
                }
                throw new TraceFormatException(source, lineNo,
                        "cannot read '" + shorten(line) + "': " + e.getMessage());
            }
        }
        if (robots.isEmpty()) {
            throw new TraceFormatException(source, 0,
                    "the trace has a header but no sample; the run wrote nothing to replay");
        }
        double last = robots.get(0).lastTime();
        for (RobotSeries r : robots) {
            last = StrictMath.min(last, r.lastTime());
        }
        if (robots.get(0).lastTime() > last) {
            notes.add(String.format(Locale.ROOT,
                    "%s: replaying up to %.3f s, the last sample every robot reached", source, last));
        }
        return new Result(robots, caps);
    }

    /** What a trace holds. */
    record Result(List<RobotSeries> robots, CapTrack caps) {
    }

    private static int split(String line, String[] out) {
        int n = 0;
        int start = 0;
        for (int i = 0; i <= line.length(); i++) {
            if (i == line.length() || line.charAt(i) == ' ') {
                if (n == out.length) {
                    return n + 1;
                }
                out[n++] = line.substring(start, i);
                start = i + 1;
            }
        }
        return n;
    }

    private static String shorten(String s) {
        return s.length() > 60 ? s.substring(0, 60) + "…" : s;
    }
}
