package org.kheperasim.sim.web;

import java.io.ByteArrayOutputStream;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.Deflater;

/**
 * Packs a run's samples for the page: every column delta-coded from the previous sample (headings
 * the short way round), as zig-zag variable-length integers, column after column, then deflated
 * (raw deflate, no header: the page's own few-line inflater reads it, so no browser API is needed).
 *
 * <p>To keep a page within its budget, the sensor values are kept at every {@code sensorStride}-th
 * sample, and only when that is not enough, the poses at every {@code poseStride}-th (the last
 * sample always kept). A 600 s run at 50 ms with one robot keeps everything.
 *
 * <p>Layout, for each robot: its kept count of times (ms), x, y (0.1 mm), heading (0.1 degree),
 * speeds, encoders, contact, arm, fingers, object, held cap + 1; then, for robots with sensors, the 8
 * proximity and 8 light columns at the sensor stride. Then the cap moves: time, cap id, x, y (each
 * cap's own previous as the base), holder + 1.
 */
final class TapeEncoder {
    /** Most samples between two kept sensor values. */
    static final int MAX_SENSOR_STRIDE = 40;

    /**
     * @param deflated     the packed samples
     * @param rawBytes     their length before deflating
     * @param poseStride   every how many samples a pose is kept
     * @param sensorStride every how many kept poses the sensor values are kept
     * @param kept         per robot, how many poses were kept
     */
    record Encoded(byte[] deflated, int rawBytes, int poseStride, int sensorStride, int[] kept) {
        /** @return the base64 text the page carries */
        String base64() {
            return java.util.Base64.getEncoder().encodeToString(deflated);
        }

        /** @return how long {@link #base64()} is, characters */
        long base64Length() {
            return 4L * ((deflated.length + 2) / 3);
        }
    }

    private TapeEncoder() {
    }

    /**
     * @param tape   the run
     * @param budget most characters the base64 text may take
     * @return the samples, thinned as little as fits the budget (over it only when the caps' moves alone exceed it)
     */
    static Encoded encode(RunTape tape, long budget) {
        return encode(tape, budget, pack(tape, 1, 1));
    }

    /**
     * @param all the samples packed whole ({@code pack(tape, 1, 1)}), when the caller has them already
     * @return as {@link #encode(RunTape, long)}
     */
    static Encoded encode(RunTape tape, long budget, Encoded all) {
        if (all.base64Length() <= budget) {
            return all;
        }
        // Estimate from the parts packed alone, then check the whole and thin more until it fits.
        int poseOnly = deflate(poses(tape, 1)).length * 4 / 3;
        int sensorsAll = StrictMath.max(1, (int) all.base64Length() - poseOnly);
        int pose = 1;
        long left = budget - poseOnly;
        if (left < budget / 4) {
            pose = (int) StrictMath.ceil(poseOnly / (budget * 0.6));
            left = budget - poseOnly / pose;
        }
        int sensor = (int) StrictMath.min(MAX_SENSOR_STRIDE,
                StrictMath.max(2, StrictMath.ceil(sensorsAll / (double) (left * pose))));
        int longest = tape.robots().stream().mapToInt(RunTape.Track::size).max().orElse(1);
        while (true) {
            Encoded e = pack(tape, pose, sensor);
            // At one pose per run what is left is the caps' moves, which are never thinned: that is the page.
            if (e.base64Length() <= budget || pose >= longest) {
                return e;
            }
            if (sensor < MAX_SENSOR_STRIDE) {
                sensor = StrictMath.min(MAX_SENSOR_STRIDE, sensor + StrictMath.max(1, sensor / 4));
            } else {
                pose += StrictMath.max(1, pose / 2);
            }
        }
    }

    /** @return the kept sample indices of {@code n} at {@code stride}: 0, stride, 2 stride, …, and the last */
    static int[] kept(int n, int stride) {
        if (n == 0) {
            return new int[0];
        }
        int m = (n - 1) / stride + 1;
        boolean lastToo = (n - 1) % stride != 0;
        int[] out = new int[m + (lastToo ? 1 : 0)];
        for (int j = 0; j < m; j++) {
            out[j] = j * stride;
        }
        if (lastToo) {
            out[m] = n - 1;
        }
        return out;
    }

    static Encoded pack(RunTape tape, int poseStride, int sensorStride) {
        Out out = new Out();
        List<RunTape.Track> robots = tape.robots();
        int[] keptCounts = new int[robots.size()];
        for (int r = 0; r < robots.size(); r++) {
            RunTape.Track t = robots.get(r);
            int[] idx = kept(t.size(), poseStride);
            keptCounts[r] = idx.length;
            IntList[] cols = t.columns();
            for (int c = 0; c < cols.length; c++) {
                out.column(cols[c], idx, cols[c] == t.h);
            }
            if (t.sensors != null) {
                int[] sidx = new int[(idx.length - 1) / sensorStride + 1];
                for (int j = 0; j < sidx.length; j++) {
                    sidx[j] = idx[j * sensorStride];
                }
                for (IntList s : t.sensors) {
                    out.column(s, sidx, false);
                }
            }
        }
        caps(out, tape.caps());
        byte[] raw = out.bytes.toByteArray();
        return new Encoded(deflate(raw), raw.length, poseStride, sensorStride, keptCounts);
    }

    private static byte[] poses(RunTape tape, int poseStride) {
        Out out = new Out();
        for (RunTape.Track t : tape.robots()) {
            int[] idx = kept(t.size(), poseStride);
            for (IntList c : t.columns()) {
                out.column(c, idx, c == t.h);
            }
        }
        caps(out, tape.caps());
        return out.bytes.toByteArray();
    }

    private static void caps(Out out, List<RunTape.CapMove> moves) {
        long prevMs = 0;
        int prevId = 0;
        for (RunTape.CapMove m : moves) {
            out.signed(m.ms() - prevMs);
            prevMs = m.ms();
        }
        for (RunTape.CapMove m : moves) {
            out.signed(m.cap() - prevId);
            prevId = m.cap();
        }
        Map<Integer, int[]> last = new HashMap<>();
        for (RunTape.CapMove m : moves) {
            int[] p = last.getOrDefault(m.cap(), new int[2]);
            out.signed(m.x10() - p[0]);
            out.signed(m.y10() - p[1]);
            last.put(m.cap(), new int[] {m.x10(), m.y10()});
        }
        for (RunTape.CapMove m : moves) {
            out.signed(m.heldBy() + 1L);
        }
    }

    static byte[] deflate(byte[] raw) {
        // The default level: within 1 % of the best size, in a quarter of its time.
        Deflater d = new Deflater(Deflater.DEFAULT_COMPRESSION, true);
        try {
            d.setInput(raw);
            d.finish();
            ByteArrayOutputStream out = new ByteArrayOutputStream(raw.length / 3 + 64);
            byte[] buf = new byte[64 * 1024];
            while (!d.finished()) {
                int n = d.deflate(buf);
                out.write(buf, 0, n);
            }
            return out.toByteArray();
        } finally {
            d.end();
        }
    }

    /** Zig-zag variable-length integers, 7 bits a byte, low bits first. */
    private static final class Out {
        final ByteArrayOutputStream bytes = new ByteArrayOutputStream(1 << 16);

        void column(IntList col, int[] idx, boolean angle) {
            long prev = 0;
            for (int i : idx) {
                long v = col.get(i);
                long d = v - prev;
                if (angle) {
                    d = Math.floorMod(d + 1800, 3600) - 1800;
                }
                signed(d);
                prev = angle ? prev + d : v;
            }
        }

        void signed(long v) {
            long z = (v << 1) ^ (v >> 63);
            while ((z & ~0x7FL) != 0) {
                bytes.write((int) ((z & 0x7F) | 0x80));
                z >>>= 7;
            }
            bytes.write((int) z);
        }
    }
}
