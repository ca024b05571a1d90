package org.kheperasim.sim.web;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.zip.Inflater;
import org.junit.jupiter.api.Test;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.engine.view.CapView;
import org.kheperasim.sim.engine.view.Contact;
import org.kheperasim.sim.engine.view.GripperView;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.testfixtures.Arenas;

/** The packed samples: what the page unpacks is what the run had, and a run too big for a page is thinned to fit. */
class TapeEncoderTest {

    /** {@code robots} robots wandering with noisy sensors for {@code samples} samples 50 ms apart, and a cap carried about. */
    private static RunTape tape(int robots, int samples, long seed) {
        Arena arena = Arenas.THREE;
        RunTape tape = new RunTape(arena);
        SplittableRandom random = new SplittableRandom(seed);
        double[] x = new double[robots];
        double[] y = new double[robots];
        double[] h = new double[robots];
        for (int r = 0; r < robots; r++) {
            x[r] = 100 + random.nextDouble(1000);
            y[r] = 100 + random.nextDouble(1000);
            h[r] = random.nextDouble(-180, 180);
        }
        for (int k = 0; k < samples; k++) {
            List<RobotView> views = new ArrayList<>();
            for (int r = 0; r < robots; r++) {
                h[r] += random.nextDouble(-8, 8);
                h[r] -= 360 * StrictMath.floor((h[r] + 180) / 360);
                x[r] += 2 * StrictMath.cos(StrictMath.toRadians(h[r]));
                y[r] += 2 * StrictMath.sin(StrictMath.toRadians(h[r]));
                int[] prox = new int[8];
                int[] light = new int[8];
                for (int i = 0; i < 8; i++) {
                    prox[i] = random.nextInt(1024);
                    light[i] = 400 + random.nextInt(100);
                }
                views.add(new RobotView(r, "r" + r, x[r], y[r], h[r], random.nextInt(-9, 10), random.nextInt(-9, 10), k * 13,
                        -k * 11, k % 97 == 0 ? Contact.LEFT : Contact.NONE, prox, light, 0, 0, "running",
                        new GripperView(180 + k % 70, false, k % 2 == 0 ? GripperState.OPEN : GripperState.CLOSED, k % 3 == 0, 0,
                                k % 5 == 0 ? 0 : -1), 0));
            }
            List<CapView> caps = List.of(new CapView(0, x[0] + 30, y[0], 15, k % 5 == 0 ? 0 : -1));
            tape.add(new Snapshot(k * 50_000_000L, views, caps), arena);
        }
        return tape;
    }

    @Test
    void whatThePageUnpacksIsWhatTheRunHad() throws Exception {
        RunTape tape = tape(3, 2000, 7);
        TapeEncoder.Encoded e = TapeEncoder.pack(tape, 1, 1);
        long[] values = unpack(e);
        int at = 0;
        for (RunTape.Track t : tape.robots()) {
            for (IntList c : t.columns()) {
                long sum = 0;
                for (int i = 0; i < t.size(); i++) {
                    sum += values[at++];
                    long want = c.get(i);
                    if (c == t.h) {
                        assertEquals(0, Math.floorMod(sum - want, 3600), "heading at " + i + " the same angle");
                    } else {
                        assertEquals(want, sum, "column value at " + i);
                    }
                }
            }
            for (IntList c : t.sensors) {
                long sum = 0;
                for (int i = 0; i < t.size(); i++) {
                    sum += values[at++];
                    assertEquals(c.get(i), sum);
                }
            }
        }
        int moves = tape.caps().size();
        assertEquals(at + 5L * moves, values.length, "then the caps' moves: time, id, x and y, holder");
        assertTrue(moves > 500, "a cap carried moves often: " + moves);
    }

    @Test
    void aSwarmsLongRunIsThinnedToFitAndSaysHowMuch() throws Exception {
        RunTape tape = tape(20, 6000, 3);
        long budget = 60_000;
        TapeEncoder.Encoded e = TapeEncoder.encode(tape, budget);
        assertTrue(e.base64Length() <= budget, e.base64Length() + " characters");
        assertTrue(e.sensorStride() == TapeEncoder.MAX_SENSOR_STRIDE && e.poseStride() > 1,
                "the sensor values thinned first, then the poses: sensors every " + e.sensorStride() + ", poses every " + e.poseStride());
        assertEquals(TapeEncoder.kept(6000, e.poseStride()).length, e.kept()[0]);
        long[] values = unpack(e);
        int n = e.kept()[0];
        int m = (n - 1) / e.sensorStride() + 1;
        assertEquals(20L * 13 * n + 16L * 16 * m + 5L * tape.caps().size(), values.length);
    }

    @Test
    void thinnedSamplesKeepTheFirstAndTheLast() {
        assertArrayEquals(new int[] {0, 3, 6, 9}, TapeEncoder.kept(10, 3));
        assertArrayEquals(new int[] {0, 3, 6, 9, 10}, TapeEncoder.kept(11, 3));
        assertArrayEquals(new int[] {0}, TapeEncoder.kept(1, 5));
        assertArrayEquals(new int[0], TapeEncoder.kept(0, 5));
    }

    /** The page's unpacking, in Java: raw inflate, then zig-zag variable-length integers. */
    private static long[] unpack(TapeEncoder.Encoded e) throws Exception {
        Inflater inflater = new Inflater(true);
        inflater.setInput(java.util.Base64.getDecoder().decode(e.base64()));
        byte[] raw = new byte[e.rawBytes()];
        int n = inflater.inflate(raw);
        assertEquals(e.rawBytes(), n);
        inflater.end();
        long[] out = new long[raw.length];
        int count = 0;
        int p = 0;
        while (p < raw.length) {
            long z = 0;
            int shift = 0;
            int b;
            do {
                b = raw[p++] & 0xFF;
                z |= (long) (b & 0x7F) << shift;
                shift += 7;
            } while ((b & 0x80) != 0);
            out[count++] = (z >>> 1) ^ -(z & 1);
        }
        return java.util.Arrays.copyOf(out, count);
    }
}
