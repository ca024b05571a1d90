package org.kheperasim.sim.engine.noise;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Counter-based noise: a draw depends only on (stream, index), and the Gaussian is a Gaussian. */
class CounterNoiseTest {

    @Test
    void aDrawDoesNotDependOnTheOrderOfDrawing() {
        CounterNoise a = new CounterNoise(7);
        CounterNoise b = new CounterNoise(7);
        double[] forward = new double[1000];
        for (int k = 0; k < forward.length; k++) {
            forward[k] = a.gaussian(k);
        }
        for (int k = forward.length - 1; k >= 0; k -= 3) {
            assertEquals(forward[k], b.gaussian(k), "draw " + k + " backwards and skipping");
        }
        assertEquals(a.uniform(123_456_789L), b.uniform(123_456_789L));
    }

    @Test
    void streamsWithOtherKeysDiffer() {
        CounterNoise a = new CounterNoise(1);
        CounterNoise b = new CounterNoise(2);
        int same = 0;
        for (int k = 0; k < 1000; k++) {
            if (a.uniform(k) == b.uniform(k)) {
                same++;
            }
        }
        assertEquals(0, same);
        assertNotEquals(a.gaussian(0), b.gaussian(0));
    }

    @Test
    void valuesArePinnedSoEveryJvmAndReleaseAgrees() {
        // Pure arithmetic on longs and doubles, tables built with StrictMath: these never change.
        // The uniforms are SplitMix64's, computed independently (in Python) for key 42.
        CounterNoise n = new CounterNoise(42);
        assertEquals(0x1.7bae644c5fd6dp-1, n.uniform(0), 0);
        assertEquals(0x1.477f199d93378p-3, n.uniform(1), 0);
        assertEquals(0x1.1d499d5c4c3e6p-2, n.uniform(2), 0);
        double[] pinned = {n.gaussian(0), n.gaussian(1), n.gaussian(2)};
        CounterNoise again = new CounterNoise(42);
        for (int k = 0; k < pinned.length; k++) {
            assertEquals(pinned[k], again.gaussian(k), 0);
        }
    }

    @Test
    void uniformsFillTheUnitInterval() {
        CounterNoise n = new CounterNoise(3);
        int[] bins = new int[10];
        int count = 200_000;
        for (int k = 0; k < count; k++) {
            double u = n.uniform(k);
            assertTrue(u >= 0 && u < 1);
            bins[(int) (u * 10)]++;
        }
        for (int b : bins) {
            assertEquals(count / 10.0, b, 5 * StrictMath.sqrt(count / 10.0), "each tenth gets its share");
        }
    }

    @Test
    void gaussiansHaveTheMomentsAndTailsOfTheStandardNormal() {
        CounterNoise n = new CounterNoise(11);
        int count = 1_000_000;
        double sum = 0;
        double sum2 = 0;
        double sum4 = 0;
        int beyond2 = 0;
        int beyond3 = 0;
        for (int k = 0; k < count; k++) {
            double g = n.gaussian(k);
            sum += g;
            sum2 += g * g;
            sum4 += g * g * g * g;
            if (StrictMath.abs(g) > 2) {
                beyond2++;
            }
            if (StrictMath.abs(g) > 3) {
                beyond3++;
            }
        }
        assertEquals(0, sum / count, 0.005, "mean");
        assertEquals(1, sum2 / count, 0.01, "variance");
        assertEquals(3, sum4 / count, 0.05, "fourth moment (kurtosis 3)");
        assertEquals(0.0455, (double) beyond2 / count, 0.002, "P(|g| > 2)");
        assertEquals(0.0027, (double) beyond3 / count, 0.0004, "P(|g| > 3), through the ziggurat's tail");
    }
}
