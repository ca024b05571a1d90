package org.kheperasim.sim.engine;

import java.util.SplittableRandom;

/**
 * One independent stream of randomness. Gaussian draws use the polar method with {@link StrictMath}, so
 * the values are the same on every JVM (the JDK's own {@code nextGaussian} algorithm may change
 * between releases).
 */
final class Noise {
    private final SplittableRandom random;
    private double spare;
    private boolean hasSpare;

    Noise(SplittableRandom random) {
        this.random = random;
    }

    /** @return a uniform value in [0, 1) */
    double uniform() {
        return random.nextDouble();
    }

    /** @return a standard normal value (Marsaglia's polar method; the pair's second value is kept for the next call) */
    double gaussian() {
        if (hasSpare) {
            hasSpare = false;
            return spare;
        }
        double u;
        double v;
        double s;
        do {
            u = random.nextDouble() * 2 - 1;
            v = random.nextDouble() * 2 - 1;
            s = u * u + v * v;
        } while (s >= 1 || s == 0);
        double m = StrictMath.sqrt(-2 * StrictMath.log(s) / s);
        spare = v * m;
        hasSpare = true;
        return u * m;
    }
}
