package org.kheperasim.sim.replay;

import java.util.Arrays;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.engine.view.Contact;
import org.kheperasim.sim.engine.view.GripperView;
import org.kheperasim.sim.engine.view.RobotView;

/**
 * One robot's samples over a run, oldest first, growing as samples are added: the time, the pose,
 * and {@link #CHANNELS} integer channels (8 proximity, 8 light, the two wheel speeds, the two
 * encoders), plus the contact and gripper state a replay draws. Safe to add to on one thread (the
 * engine's) while another (the window's) reads.
 */
public final class RobotSeries {
    /** Channels per sample. */
    public static final int CHANNELS = 20;
    /** First proximity channel (8 of them). */
    public static final int PROXIMITY = 0;
    /** First light channel (8 of them). */
    public static final int LIGHT = 8;
    /** Left, then right wheel speed, speed units (1 unit = 8 mm/s). */
    public static final int SPEED = 16;
    /** Left, then right encoder, pulses (1 pulse = 0.08 mm). */
    public static final int ENCODER = 18;

    private static final Contact[] CONTACTS = Contact.values();
    private static final GripperState[] FINGERS = GripperState.values();

    private double[] times = new double[256];
    private float[] xs = new float[256];
    private float[] ys = new float[256];
    private float[] headings = new float[256];
    private int[] values = new int[256 * CHANNELS];
    /** contact ordinal | fingers ordinal << 4 | object << 7 | arm << 8 | (held cap + 1) << 16. */
    private long[] states = new long[256];
    private int size;

    /** @return the name of channel {@code c}, as a CSV column */
    public static String channelName(int c) {
        if (c < LIGHT) {
            return "prox" + c;
        }
        if (c < SPEED) {
            return "light" + (c - LIGHT);
        }
        if (c < ENCODER) {
            return c == SPEED ? "speed_l" : "speed_r";
        }
        return c == ENCODER ? "enc_l" : "enc_r";
    }

    /** @param t simulated time, s (not before the last sample's) @param r the robot then */
    public void add(double t, RobotView r) {
        int[] ch = new int[CHANNELS];
        // Eight sensor channels whatever the robot, as the trace's columns: one with fewer keeps 0 in the rest.
        int n = StrictMath.min(8, r.sensorCount());
        for (int i = 0; i < n; i++) {
            ch[PROXIMITY + i] = r.proximity(i);
            ch[LIGHT + i] = r.light(i);
        }
        ch[SPEED] = r.speedLeft();
        ch[SPEED + 1] = r.speedRight();
        ch[ENCODER] = r.encoderLeft();
        ch[ENCODER + 1] = r.encoderRight();
        GripperView g = r.gripper();
        add(t, r.x(), r.y(), r.headingDeg(), ch, r.contact(), g.armPosition(), g.fingers(),
                g.objectPresent(), g.heldCap());
    }

    /**
     * @param t simulated time, s (not before the last sample's)
     * @param x mm
     * @param y mm
     * @param headingDeg degrees
     * @param channels {@link #CHANNELS} values
     * @param contact the contact side
     * @param arm the arm's position
     * @param fingers the fingers' state
     * @param object the object sensor
     * @param heldCap the held cap's id, or -1
     */
    public synchronized void add(double t, double x, double y, double headingDeg, int[] channels, Contact contact,
            int arm, GripperState fingers, boolean object, int heldCap) {
        if (size > 0 && t < times[size - 1]) {
            throw new IllegalArgumentException("sample at " + t + " s comes before the last one at "
                    + times[size - 1] + " s");
        }
        if (size == times.length) {
            int n = size * 2;
            times = Arrays.copyOf(times, n);
            xs = Arrays.copyOf(xs, n);
            ys = Arrays.copyOf(ys, n);
            headings = Arrays.copyOf(headings, n);
            values = Arrays.copyOf(values, n * CHANNELS);
            states = Arrays.copyOf(states, n);
        }
        times[size] = t;
        xs[size] = (float) x;
        ys[size] = (float) y;
        headings[size] = (float) headingDeg;
        System.arraycopy(channels, 0, values, size * CHANNELS, CHANNELS);
        states[size] = contact.ordinal() | (long) fingers.ordinal() << 4 | (object ? 1L : 0L) << 7
                | (long) (arm & 0xFF) << 8 | (long) (heldCap + 1) << 16;
        size++;
    }

    /** @return samples so far */
    public synchronized int size() {
        return size;
    }

    /** @param k sample index @return its time, s */
    public synchronized double time(int k) {
        return times[k];
    }

    /** @param c channel @param k sample index @return the value */
    public synchronized int value(int c, int k) {
        return values[k * CHANNELS + c];
    }

    /** @return the last sample's time, s, or 0 without samples */
    public synchronized double lastTime() {
        return size == 0 ? 0 : times[size - 1];
    }

    /** @param t time, s @return the index of the last sample at or before {@code t}, or -1 */
    public synchronized int indexAt(double t) {
        int i = Arrays.binarySearch(times, 0, size, t);
        if (i >= 0) {
            while (i + 1 < size && times[i + 1] == t) {
                i++;
            }
            return i;
        }
        return -i - 2;
    }

    /**
     * @param id the robot's index
     * @param name its name
     * @param k a sample index
     * @param controller the controller's state to show
     * @return the robot at that sample, as the panels draw it (collisions and distance not kept: 0)
     */
    public synchronized RobotView view(int id, String name, int k, String controller) {
        int[] prox = Arrays.copyOfRange(values, k * CHANNELS + PROXIMITY, k * CHANNELS + PROXIMITY + 8);
        int[] light = Arrays.copyOfRange(values, k * CHANNELS + LIGHT, k * CHANNELS + LIGHT + 8);
        long s = states[k];
        GripperView g = new GripperView((int) (s >> 8 & 0xFF), false, FINGERS[(int) (s >> 4 & 0x7)], (s >> 7 & 1) == 1,
                0, (int) (s >> 16) - 1);
        return new RobotView(id, name, xs[k], ys[k], headings[k], values[k * CHANNELS + SPEED],
                values[k * CHANNELS + SPEED + 1],
                values[k * CHANNELS + ENCODER], values[k * CHANNELS + ENCODER + 1],
                CONTACTS[(int) (s & 0xF)], prox, light,
                0, 0, controller, g, 0);
    }

    /** @param upTo last sample index included @return the path x0, y0, x1, y1, … mm up to it */
    public synchronized float[] trail(int upTo) {
        int n = StrictMath.min(upTo + 1, size);
        float[] out = new float[StrictMath.max(0, n) * 2];
        for (int k = 0; k < n; k++) {
            out[2 * k] = xs[k];
            out[2 * k + 1] = ys[k];
        }
        return out;
    }

    /**
     * The samples in a span, thinned to at most {@code maxPoints} (every n-th), for drawing.
     *
     * @param from start, s
     * @param to end, s
     * @param channels which channels
     * @param maxPoints most samples returned (0: all)
     * @return row 0 the times, then one row per channel
     */
    public synchronized double[][] extract(double from, double to, int[] channels, int maxPoints) {
        int a = StrictMath.max(0, indexAt(from));
        int b = indexAt(to);
        int n = b < a ? 0 : b - a + 1;
        int stride = maxPoints <= 0 || n <= maxPoints ? 1 : (n + maxPoints - 1) / maxPoints;
        int m = n == 0 ? 0 : (n + stride - 1) / stride;
        double[][] out = new double[1 + channels.length][m];
        for (int j = 0; j < m; j++) {
            int k = a + j * stride;
            out[0][j] = times[k];
            for (int c = 0; c < channels.length; c++) {
                out[1 + c][j] = values[k * CHANNELS + channels[c]];
            }
        }
        return out;
    }
}
