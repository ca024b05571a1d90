package org.kheperasim.sim.arena;

import java.math.BigDecimal;

/** Number checks and formatting shared by the model records and the file format. */
final class Numbers {

    private Numbers() {
    }

    /**
     * The shortest plain decimal that reads back as exactly {@code d}: {@code 100}, {@code 1219.2},
     * {@code 0.001}; never an exponent, never a trailing {@code .0}.
     */
    static String format(double d) {
        return BigDecimal.valueOf(d).stripTrailingZeros().toPlainString();
    }

    /**
     * A number as a message shows it: the plain form of {@link #format} when it is short, else
     * the exponent form ({@code 1.0E308}), so that no message grows to hundreds of digits.
     */
    static String brief(double d) {
        String plain = format(d);
        return plain.length() <= 24 ? plain : Double.toString(d);
    }

    /**
     * Checks that {@code value} is finite and returns it with negative zero turned into zero, so
     * that a record compares equal to its own written-and-read-back copy.
     *
     * @throws IllegalArgumentException naming {@code what} when the value is NaN or infinite
     */
    static double finite(String what, double value) {
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException(what + " is " + value + "; give a finite number");
        }
        return value + 0.0;
    }

    /**
     * Checks that {@code value} is finite and greater than zero.
     *
     * @param unit the unit named in the message, e.g. {@code "mm"}
     * @throws IllegalArgumentException naming {@code what}, the value and the rule
     */
    static double positive(String what, double value, String unit) {
        finite(what, value);
        if (!(value > 0)) {
            throw new IllegalArgumentException(
                    what + " is " + brief(value) + "; it must be greater than 0 " + unit);
        }
        return value;
    }
}
