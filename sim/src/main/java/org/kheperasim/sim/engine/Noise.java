package org.kheperasim.sim.engine;

import java.util.SplittableRandom;

/**
 * One independent stream of randomness. Gaussian draws use Box–Muller with {@link StrictMath}, so
 * the values are the same on every JVM (the JDK's own {@code nextGaussian} algorithm may change
 * between releases).
 */
final class Noise {
    private final SplittableRandom random;

    Noise(SplittableRandom random) {
        this.random = random;
    }

    /** @return a uniform value in [0, 1) */
    double uniform() {
        return random.nextDouble();
    }

    /** @return a standard normal value */
    double gaussian() {
        double u1 = 1.0 - random.nextDouble();
        double u2 = random.nextDouble();
        return StrictMath.sqrt(-2.0 * StrictMath.log(u1)) * StrictMath.cos(2.0 * StrictMath.PI * u2);
    }
}
