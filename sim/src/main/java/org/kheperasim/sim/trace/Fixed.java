package org.kheperasim.sim.trace;

/**
 * Locale-free fixed-point formatting, the same on every machine and much faster than
 * {@code String.format} (traces write tens of numbers per line).
 */
public final class Fixed {
    private static final long[] POW10 = {1, 10, 100, 1_000, 10_000, 100_000, 1_000_000};

    private Fixed() {
    }

    /**
     * Append {@code value} rounded half up to {@code decimals} places, e.g. {@code -0.5 → "-0.500"}
     * for 3 places; a value that rounds to zero prints without a sign.
     *
     * @param out where to append
     * @param value the value (finite)
     * @param decimals 0..6
     * @return {@code out}
     */
    public static StringBuilder append(StringBuilder out, double value, int decimals) {
        long scaled = (long) StrictMath.floor(StrictMath.abs(value) * POW10[decimals] + 0.5);
        if (value < 0 && scaled != 0) {
            out.append('-');
        }
        out.append(scaled / POW10[decimals]);
        if (decimals > 0) {
            out.append('.');
            String frac = Long.toString(scaled % POW10[decimals]);
            for (int i = frac.length(); i < decimals; i++) {
                out.append('0');
            }
            out.append(frac);
        }
        return out;
    }

    /** @return {@code value} formatted with {@code decimals} places */
    public static String format(double value, int decimals) {
        return append(new StringBuilder(), value, decimals).toString();
    }
}
