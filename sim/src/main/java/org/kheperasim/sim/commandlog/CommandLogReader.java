package org.kheperasim.sim.commandlog;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;

/**
 * Reads a command log ({@link CommandLogWriter}) line by line, in the order it was written, which is
 * the order an open-loop replay needs it in: the whole log is never held in memory. A line that is
 * not what the format allows ends the reading with a {@link LogFormatException} naming the line.
 */
public final class CommandLogReader implements AutoCloseable {
    /** What happened, in the log's order. */
    public sealed interface Event {
    }

    /**
     * A driver's wake time as the engine reads it next.
     *
     * @param robot    the robot
     * @param initial  true for the wake at the run's start (then {@code ticks} is absolute)
     * @param ticks    the wake tick, absolute or after the turn's tick; ignored when {@code ended}
     * @param ended    true when the driver has ended
     */
    public record Wake(int robot, boolean initial, long ticks, boolean ended) implements Event {
    }

    /**
     * A command that reached a robot's link.
     *
     * @param kind  {@code v} speeds, {@code p} position counters, {@code a} arm, {@code f} fingers, {@code r} a
     *              read that brought poll reply {@code a} in early, {@code i} a read that made the
     *              vision turret take an image
     * @param robot the robot
     * @param now   the controller's simulated time, ns
     * @param a     left speed or counter, the arm's position, 1 for closed fingers
     * @param b     right speed or counter (0 for the others)
     */
    public record Command(char kind, int robot, long now, int a, int b) implements Event {
    }

    /** @param robot the robot whose wheels were stopped at once */
    public record Stop(int robot) implements Event {
    }

    /** @param nanos where the run, stopped early (a signal, a Stop), ends, simulated ns */
    public record EarlyEnd(long nanos) implements Event {
    }

    /** @param json the run's own result, one line of JSON */
    public record Claim(String json) implements Event {
    }

    private final BufferedReader in;
    private final LogHeader header;
    private long lineNumber;
    private long events;
    private boolean ended;

    /**
     * Reads the header.
     *
     * @param in the log's text
     * @throws LogFormatException if it is not a command log
     */
    public CommandLogReader(BufferedReader in) {
        this.in = in;
        String magic = line();
        if (magic == null) {
            throw new TornLogException(0, "the log is empty");
        }
        if (!LogHeader.MAGIC.equals(magic)) {
            throw new LogFormatException(1, "not a command log: it should start with '" + LogHeader.MAGIC + "'");
        }
        long seed = Long.parseLong(field("seed"));
        String arena = field("arena");
        long end = Long.parseLong(field("end-ns"));
        long sample = Long.parseLong(field("sample-ms"));
        int n = Integer.parseInt(field("robots"));
        if (n < 1 || n > 100_000) {
            throw new LogFormatException(lineNumber, "robots " + n + " is out of range");
        }
        List<LogHeader.Robot> robots = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            String[] r = field("robot").split(" ", 3);
            if (r.length != 3 || !r[0].equals(Integer.toString(i))) {
                throw new LogFormatException(lineNumber, "expected 'robot " + i + " CLASS NAME'");
            }
            String s = field("settings");
            if (!s.startsWith(i + " ")) {
                throw new LogFormatException(lineNumber, "expected 'settings " + i + " ...'");
            }
            String m = field("mode");
            if (!m.startsWith(i + " ")) {
                throw new LogFormatException(lineNumber, "expected 'mode " + i + " tethered|onboard|onboard-steps'");
            }
            robots.add(new LogHeader.Robot(r[1], r[2], s.substring(s.indexOf(' ') + 1),
                    m.substring(m.indexOf(' ') + 1)));
        }
        this.header = new LogHeader(seed, arena, end, sample, robots);
    }

    /** @return the log's header */
    public LogHeader header() {
        return header;
    }

    /** @return the number of the line read last, from 1 */
    public long lineNumber() {
        return lineNumber;
    }

    /**
     * @return the next event, or null after the end line
     * @throws LogFormatException for a line the format does not allow, or a log that stops before its end line
     */
    public Event next() {
        if (ended) {
            return null;
        }
        String l = line();
        if (l == null) {
            throw new TornLogException(lineNumber,
                    "the log stops before its end line (torn: the run did not finish it)");
        }
        try {
            if (l.startsWith("claim ")) {
                return new Claim(l.substring(6));
            }
            if (l.startsWith("end ")) {
                long count = Long.parseLong(l.substring(4));
                if (count != events) {
                    throw new LogFormatException(lineNumber,
                            "the end line counts " + count + " events, the log holds " + events);
                }
                ended = true;
                return null;
            }
            events++;
            String[] f = l.split(" ");
            char kind = f[0].length() == 1 ? f[0].charAt(0) : '?';
            if (kind == 'q') {
                count(f, 2);
                return new EarlyEnd(Long.parseLong(f[1]));
            }
            int robot = robot(f);
            return switch (kind) {
                case 'W', 'w' -> {
                    count(f, 3);
                    boolean x = f[2].equals("x");
                    yield new Wake(robot, kind == 'W', x ? 0 : Long.parseLong(f[2]), x);
                }
                case 'v', 'p' -> {
                    count(f, 5);
                    yield new Command(kind, robot, Long.parseLong(f[2]), Integer.parseInt(f[3]),
                            Integer.parseInt(f[4]));
                }
                case 'a', 'f', 'r' -> {
                    count(f, 4);
                    yield new Command(kind, robot, Long.parseLong(f[2]), Integer.parseInt(f[3]), 0);
                }
                case 'i' -> {
                    count(f, 3);
                    yield new Command(kind, robot, Long.parseLong(f[2]), 0, 0);
                }
                case 'e' -> {
                    count(f, 2);
                    yield new Stop(robot);
                }
                default -> throw new LogFormatException(lineNumber, "unknown event '" + shorten(l) + "'");
            };
        } catch (NumberFormatException e) {
            throw new LogFormatException(lineNumber, "a number is malformed in '" + shorten(l) + "'");
        }
    }

    private int robot(String[] f) {
        if (f.length < 2) {
            throw new LogFormatException(lineNumber, "an event without a robot");
        }
        int r = Integer.parseInt(f[1]);
        if (r < 0 || r >= header.robots().size()) {
            throw new LogFormatException(lineNumber,
                    "robot " + r + " is not one of the run's " + header.robots().size());
        }
        return r;
    }

    private void count(String[] f, int n) {
        if (f.length != n) {
            throw new LogFormatException(lineNumber,
                    "'" + f[0] + "' takes " + (n - 1) + " fields, this line has " + (f.length - 1));
        }
    }

    private String field(String name) {
        String l = line();
        if (l == null) {
            throw new TornLogException(lineNumber, "the log stops in its header");
        }
        if (!l.startsWith(name + " ")) {
            throw new LogFormatException(lineNumber, "expected the header line '" + name + " ...'");
        }
        return l.substring(name.length() + 1);
    }

    private String line() {
        try {
            String l = in.readLine();
            if (l != null) {
                lineNumber++;
                if (l.length() > 1 << 20) {
                    throw new LogFormatException(lineNumber, "a line over 1 MiB");
                }
            }
            return l;
        } catch (java.io.EOFException e) {
            throw new TornLogException(lineNumber, "the log's compressed stream stops before its end (torn)");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the command log: " + e.getMessage(), e);
        }
    }

    private static String shorten(String s) {
        return s.length() <= 80 ? s : s.substring(0, 77) + "...";
    }

    @Override
    public void close() {
        try {
            in.close();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
