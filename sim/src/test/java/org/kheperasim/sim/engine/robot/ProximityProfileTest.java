package org.kheperasim.sim.engine.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * A profile's reading at a distance is the table's linear interpolation between the two distances
 * around it: the same value, to the bit, for even and uneven tables, at and between their distances.
 */
class ProximityProfileTest {
    /** The interpolation, looked up from the table's start. */
    private static double reference(ProximityProfile p, double d) {
        double[] ds = p.distancesMm();
        double[] vs = p.values();
        if (d <= ds[0]) {
            return vs[0];
        }
        if (d >= ds[ds.length - 1]) {
            return vs[vs.length - 1];
        }
        int i = 1;
        while (ds[i] < d) {
            i++;
        }
        double t = (d - ds[i - 1]) / (ds[i] - ds[i - 1]);
        return vs[i - 1] + t * (vs[i] - vs[i - 1]);
    }

    @Test
    void readingsAreTheTablesInterpolationForEvenAndUnevenTables() {
        // The bundled Khepera's table (khepera1.yaml), and an even one whose steps are no round numbers.
        ProximityProfile even = new ProximityProfile("khepera1", new double[] {0, 5, 10, 15, 20, 25, 30, 35, 40, 45,
            50, 55, 60}, new double[] {1023, 985, 880, 745, 600, 455, 325, 215, 130, 70, 30, 10, 0});
        double[] tenths = new double[61];
        double[] falling = new double[61];
        for (int k = 0; k <= 60; k++) {
            tenths[k] = k * 0.1;
            falling[k] = 1000 - k * k * 0.27;
        }
        ProximityProfile fine = new ProximityProfile("tenths", tenths, falling);
        ProximityProfile uneven = new ProximityProfile("uneven", new double[] {0.5, 0.6, 3, 3.1, 17, 40, 41, 90},
                new double[] {1000, 990, 800, 795, 300, 40, 35, 0});
        // Dense at the far end: an even table's index would lie past the right one.
        ProximityProfile late = new ProximityProfile("late",
                new double[] {0, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60},
                new double[] {1023, 600, 500, 420, 350, 280, 200, 150, 90, 40, 10, 0});
        ProximityProfile two = new ProximityProfile("two", new double[] {0, 60}, new double[] {1023, 0});
        SplittableRandom random = new SplittableRandom(7);
        for (ProximityProfile p : new ProximityProfile[] {even, fine, uneven, late, two}) {
            double[] ds = p.distancesMm();
            for (double d : ds) {
                for (double at : new double[] {d, Math.nextDown(d), Math.nextUp(d)}) {
                    assertEquals(reference(p, at), p.valueAt(at), 0.0, p + " at " + at);
                }
            }
            double span = ds[ds.length - 1] - ds[0];
            for (int k = 0; k < 100_000; k++) {
                double at = ds[0] - 1 + random.nextDouble() * (span + 2);
                assertEquals(reference(p, at), p.valueAt(at), 0.0, p + " at " + at);
            }
        }
    }
}
