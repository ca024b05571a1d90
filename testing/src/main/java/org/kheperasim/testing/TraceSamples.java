package org.kheperasim.testing;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.kheperasim.sim.testkit.TestKit;

/**
 * The samples of a trace that a test asks about: each robot's pose and contact side at every sample,
 * and each cap's moves. The trace is checked by the simulator's own reader first, so a damaged file is
 * refused with its line; then the lines are split here, once.
 */
final class TraceSamples {
    /** One robot's samples, in time order; the arrays are {@link #size} long. */
    static final class Series {
        long[] nanos = new long[64];
        double[] x = new double[64];
        double[] y = new double[64];
        double[] heading = new double[64];
        String[] contact = new String[64];
        int size;

        void add(long t, double px, double py, double h, String c) {
            if (size == nanos.length) {
                int n = size * 2;
                nanos = Arrays.copyOf(nanos, n);
                x = Arrays.copyOf(x, n);
                y = Arrays.copyOf(y, n);
                heading = Arrays.copyOf(heading, n);
                contact = Arrays.copyOf(contact, n);
            }
            nanos[size] = t;
            x[size] = px;
            y[size] = py;
            heading[size] = h;
            contact[size] = c;
            size++;
        }

        /** @return the index of the last sample at or before {@code t}, or -1 */
        int indexAt(long t) {
            int i = Arrays.binarySearch(nanos, 0, size, t);
            return i >= 0 ? i : -i - 2;
        }
    }

    /**
     * A cap's state from a time on (a trace writes a cap's line at the first sample and whenever it moved).
     *
     * @param nanos simulated time, ns
     * @param x centre, mm
     * @param y centre, mm
     * @param heldBy robot holding it, or -1
     */
    record CapState(long nanos, double x, double y, int heldBy) {
    }

    final Map<String, String> header;
    final List<Series> robots = new ArrayList<>();
    final List<List<CapState>> caps = new ArrayList<>();

    private TraceSamples(Map<String, String> header) {
        this.header = header;
    }

    /**
     * @param text a trace
     * @param source how errors name it (the file)
     * @return its samples
     * @throws RuntimeException (the simulator's trace format error) naming {@code source:line}
     */
    static TraceSamples parse(String text, String source) {
        TraceSamples s = new TraceSamples(TestKit.traceHeader(text, source));
        int pos = 0;
        int end = text.length();
        while (pos < end) {
            int nl = text.indexOf('\n', pos);
            String line = text.substring(pos, nl);
            pos = nl + 1;
            if (line.isEmpty() || line.charAt(0) == '#') {
                continue;
            }
            String[] f = line.split(" ", 7);
            long t = nanos(f[0]);
            if (f[1].equals("cap")) {
                int id = Integer.parseInt(f[2]);
                while (s.caps.size() <= id) {
                    s.caps.add(new ArrayList<>());
                }
                s.caps.get(id).add(new CapState(t, Double.parseDouble(f[3]), Double.parseDouble(f[4]),
                        Integer.parseInt(f[5])));
            } else {
                int robot = Integer.parseInt(f[1]);
                while (s.robots.size() <= robot) {
                    s.robots.add(new Series());
                }
                // f[6] is "speed_r enc_l enc_r contact prox0 ...": the contact is its fourth word.
                String rest = f[6];
                int contactStart = nthSpace(rest, 3) + 1;
                String contact = rest.substring(contactStart, rest.indexOf(' ', contactStart));
                s.robots.get(robot).add(t, Double.parseDouble(f[2]), Double.parseDouble(f[3]), Double.parseDouble(f[4]),
                        contact);
            }
        }
        return s;
    }

    /** @return the position of the n-th space (1-based) in {@code s} */
    private static int nthSpace(String s, int n) {
        int at = -1;
        for (int i = 0; i < n; i++) {
            at = s.indexOf(' ', at + 1);
        }
        return at;
    }

    /** A trace's time, 3 decimals of a second, as nanoseconds (exactly, without a binary fraction). */
    static long nanos(String seconds) {
        int dot = seconds.indexOf('.');
        long whole = Long.parseLong(seconds.substring(0, dot));
        long millis = Long.parseLong(seconds.substring(dot + 1));
        return (whole * 1000 + millis) * 1_000_000L;
    }

    /**
     * @param cap a cap's index
     * @param t simulated time, ns
     * @return its state at {@code t} (its first when {@code t} comes before it)
     */
    CapState capAt(int cap, long t) {
        List<CapState> moves = caps.get(cap);
        int lo = 0;
        int hi = moves.size() - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (moves.get(mid).nanos() <= t) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return moves.get(lo);
    }
}
