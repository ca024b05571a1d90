package org.kheperasim.sim.engine.noise;

/**
 * One stream of randomness with random access: draw {@code k} is a pure function of the stream's
 * key and {@code k}. So a draw never depends on how many draws were made before it, or in what
 * order: the engine may skip work it does not need, or do it in another order, and every value
 * that is computed stays the same.
 *
 * <p>The generator is the SplitMix64 output function applied to a Weyl sequence (key + k·γ), a
 * well-studied construction that passes BigCrush; normal variates use the ziggurat method (see
 * {@link Ziggurat}), in plain arithmetic apart from rare tail and wedge draws, so the values are the
 * same on every JVM.
 */
public final class CounterNoise {
    /** The golden-ratio increment of SplitMix64's Weyl sequence. */
    private static final long GAMMA = 0x9E3779B97F4A7C15L;
    private static final double UNIT = 0x1.0p-53;

    private final long key;

    /** @param key the stream's key, drawn once per run from the run's seed */
    public CounterNoise(long key) {
        this.key = key;
    }

    /** @return the stream's key */
    public long key() {
        return key;
    }

    /** @param index the draw's index, ≥ 0 @return 64 random bits for that draw */
    public long bits(long index) {
        return mix(key + (index + 1) * GAMMA);
    }

    /** @param index the draw's index @return a uniform value in [0, 1) */
    public double uniform(long index) {
        return (bits(index) >>> 11) * UNIT;
    }

    /** @param index the draw's index @return a standard normal value */
    public double gaussian(long index) {
        long b = bits(index);
        double x = Ziggurat.fast(b);
        return x == x ? x : Ziggurat.normal(b, this, index);
    }

    /**
     * Further bits for draw {@code index} when one 64-bit value was not enough (a rejected
     * ziggurat attempt): attempt {@code a ≥ 1} of draw {@code index}.
     */
    long extraBits(long index, int attempt) {
        return mix(bits(index) + attempt * GAMMA);
    }

    /** SplitMix64's finaliser (Stafford's variant 13). */
    static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
