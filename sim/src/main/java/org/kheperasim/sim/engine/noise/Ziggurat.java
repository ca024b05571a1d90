package org.kheperasim.sim.engine.noise;

/**
 * Standard normal variates by the ziggurat method of Marsaglia and Tsang (2000), with 128 layers:
 * about 99 % of draws take one table lookup, one multiplication and one comparison, with no
 * transcendental function. The tables are built once with {@link StrictMath}, so they are the same on
 * every JVM; the rare wedge and tail draws use {@link StrictMath} too.
 *
 * <p>Every random value a draw needs comes from its own stream at fixed counter positions, so a
 * draw is a pure function of (stream, index), whatever else is drawn.
 */
final class Ziggurat {
    private static final int LAYERS = 128;
    /** Where the base layer's tail begins, for 128 layers. */
    private static final double R = 3.442619855899;
    /** The area of each layer (and of the base with its tail), for 128 layers. */
    private static final double V = 9.91256303526217e-3;
    private static final double UNIT = 0x1.0p-53;
    private static final int TAIL_ATTEMPTS = 1 << 20;

    /** Right edge of each layer; X[0] is the base's equivalent width, X[LAYERS] = 0. */
    private static final double[] X = new double[LAYERS + 1];
    /** The density (unnormalised) at each edge. */
    private static final double[] F = new double[LAYERS + 1];

    static {
        X[0] = V / density(R);
        X[1] = R;
        for (int i = 1; i < LAYERS - 1; i++) {
            X[i + 1] = StrictMath.sqrt(-2 * StrictMath.log(V / X[i] + density(X[i])));
        }
        X[LAYERS] = 0;
        for (int i = 0; i <= LAYERS; i++) {
            F[i] = density(X[i]);
        }
    }

    private Ziggurat() {
    }

    private static double density(double x) {
        return StrictMath.exp(-0.5 * x * x);
    }

    /**
     * The common case, inlined by the caller: the point falls inside its layer's rectangle.
     *
     * @param bits the draw's first 64 random bits
     * @return the normal value, or NaN when the slow path ({@link #normal}) must decide
     */
    static double fast(long bits) {
        int layer = (int) (bits & (LAYERS - 1));
        double x = (bits >>> 11) * UNIT * X[layer];
        // The sign comes from bit 7, set without a branch (it is a coin toss: a branch would mispredict half the time).
        return x < X[layer + 1] ? Double.longBitsToDouble(Double.doubleToRawLongBits(x) | ((bits & LAYERS) << 56))
                : Double.NaN;
    }

    /**
     * @param first the draw's first 64 random bits
     * @param stream where further bits come from
     * @param index the draw's index in that stream
     * @return a standard normal value
     */
    static double normal(long first, CounterNoise stream, long index) {
        long bits = first;
        for (int attempt = 0; ; attempt++) {
            if (attempt > 0) {
                bits = stream.extraBits(index, 3 * attempt);
            }
            int layer = (int) (bits & (LAYERS - 1));
            boolean negative = (bits & LAYERS) != 0;
            double x = (bits >>> 11) * UNIT * X[layer];
            if (x < X[layer + 1]) {
                return negative ? -x : x;
            }
            if (layer == 0) {
                double t = tail(stream, index);
                return negative ? -t : t;
            }
            double u = (stream.extraBits(index, 3 * attempt + 1) >>> 11) * UNIT;
            double y = F[layer + 1] + u * (F[layer] - F[layer + 1]);
            int below = below(layer, x, y);
            if (below > 0 || below == 0 && y < density(x)) {
                return negative ? -x : x;
            }
        }
    }

    /**
     * Far from the curve no exponential is needed to tell whether (x, y) lies under it: within a
     * layer, where the density is convex (x ≥ 1) it lies under the chord between the layer's edges
     * and over the tangents there, and where it is concave (x ≤ 1) the other way round. A point
     * clearly (by {@link #CLEAR}, far more than the rounding of these lines) below the lower line
     * or above the upper one is decided so, exactly as comparing it with {@code StrictMath.exp}
     * would; only the rest (about one in twelve wedge draws) takes the exponential. The draws are
     * the same as without this shortcut, only cheaper.
     *
     * @return 1: under the curve; -1: over it; 0: too close to tell without the exponential
     */
    private static int below(int layer, double x, double y) {
        double a = X[layer + 1];
        double b = X[layer];
        double fa = F[layer + 1];
        double fb = F[layer];
        double chord = fa + (fb - fa) * (x - a) / (b - a);
        double tangentA = fa * (1 - a * (x - a));
        double tangentB = fb * (1 - b * (x - b));
        if (a >= 1) {
            if (y < StrictMath.max(tangentA, tangentB) - CLEAR) {
                return 1;
            }
            return y > chord + CLEAR ? -1 : 0;
        }
        if (b <= 1) {
            if (y < chord - CLEAR) {
                return 1;
            }
            return y > StrictMath.min(tangentA, tangentB) + CLEAR ? -1 : 0;
        }
        return 0;
    }

    /** How clearly a point must lie off the bounding lines, in density units (at most 1). */
    private static final double CLEAR = 1e-12;

    /** A value from the normal tail beyond R (Marsaglia's method for the tail). */
    private static double tail(CounterNoise stream, long index) {
        for (int k = 0; k < TAIL_ATTEMPTS; k++) {
            double u1 = ((stream.extraBits(index, 1_000_000 + 2 * k) >>> 11) + 1) * UNIT;
            double u2 = ((stream.extraBits(index, 1_000_001 + 2 * k) >>> 11) + 1) * UNIT;
            double a = -StrictMath.log(u1) / R;
            double b = -StrictMath.log(u2);
            if (2 * b > a * a) {
                return R + a;
            }
        }
        return R;
    }
}
