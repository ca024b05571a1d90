package org.kheperasim.link.tool;

import java.util.List;
import java.util.regex.Pattern;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * Converters for numbers on the command line. Picocli's own would take {@code NaN},
 * {@code Infinity} and hex such as {@code 0x1p10} as doubles; these take plain decimals only and
 * check the range, naming the value and what to give instead.
 */
public final class CliNumbers {

    /** A plain decimal: {@code 12}, {@code -0.5}, {@code .25}, {@code 1.5e3}. */
    public static final Pattern DECIMAL = Pattern.compile("[+-]?+(\\d++(\\.\\d*+)?+|\\.\\d++)([eE][+-]?+\\d++)?+");
    /** The Khepera's line speeds, set by its mode jumper. */
    public static final List<Integer> KHEPERA_BAUDS = List.of(9600, 19200, 38400, 57600, 115200);
    /** The longest run, seconds (its simulated nanoseconds must fit a long): about three years. */
    public static final double MAX_SECONDS = 1e8;

    private CliNumbers() {
    }

    /**
     * @param text what the user typed
     * @return it as a finite double
     * @throws TypeConversionException when it is not a plain decimal
     */
    public static double decimal(String text) {
        String t = text.strip();
        if (t.length() > 40 || !DECIMAL.matcher(t).matches()) {
            throw new TypeConversionException("'" + shorten(text)
                    + "' is not a decimal number; write it like 12, 0.5 or 1.5e3");
        }
        double d = Double.parseDouble(t);
        if (!Double.isFinite(d)) {
            throw new TypeConversionException("'" + shorten(text) + "' is too large; give a finite number");
        }
        return d;
    }

    /** Seconds, finite and greater than 0 (at most {@link #MAX_SECONDS}). */
    public static final class PositiveSeconds implements ITypeConverter<Double> {
        @Override
        public Double convert(String value) {
            double d = decimal(value);
            if (!(d > 0) || d > MAX_SECONDS) {
                throw new TypeConversionException("'" + shorten(value) + "' seconds: give a number of seconds greater"
                        + " than 0 and at most " + (long) MAX_SECONDS + ", e.g. 60 or 0.5");
            }
            return d;
        }
    }

    /** A plain decimal greater than 0. */
    public static final class PositiveDecimal implements ITypeConverter<Double> {
        @Override
        public Double convert(String value) {
            double d = decimal(value);
            if (!(d > 0)) {
                throw new TypeConversionException("'" + shorten(value) + "': give a number greater than 0");
            }
            return d;
        }
    }

    /** A plain decimal, 0 or more. */
    public static final class NonNegativeDecimal implements ITypeConverter<Double> {
        @Override
        public Double convert(String value) {
            double d = decimal(value);
            if (d < 0) {
                throw new TypeConversionException("'" + shorten(value) + "' is negative; give 0 or more");
            }
            return d;
        }
    }

    /** A whole number greater than 0. */
    public static final class PositiveInt implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            int n = integer(value);
            if (n < 1) {
                throw new TypeConversionException("'" + shorten(value) + "': give a whole number of 1 or more");
            }
            return n;
        }
    }

    /** A whole number, 0 or more. */
    public static final class NonNegativeInt implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            int n = integer(value);
            if (n < 0) {
                throw new TypeConversionException("'" + shorten(value)
                        + "' is negative: give a whole number of 0 or more");
            }
            return n;
        }
    }

    /** A whole number greater than 0, as a long. */
    public static final class PositiveLong implements ITypeConverter<Long> {
        @Override
        public Long convert(String value) {
            long n = longInteger(value);
            if (n < 1) {
                throw new TypeConversionException("'" + shorten(value) + "': give a whole number of 1 or more");
            }
            return n;
        }
    }

    /** Any whole number that fits 64 bits, in decimal (a seed). */
    public static final class AnyLong implements ITypeConverter<Long> {
        @Override
        public Long convert(String value) {
            return longInteger(value);
        }
    }

    /** One of {@link #KHEPERA_BAUDS}. */
    public static final class Baud implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            String t = value.strip();
            for (int b : KHEPERA_BAUDS) {
                if (t.equals(Integer.toString(b))) {
                    return b;
                }
            }
            throw new TypeConversionException("baud '" + shorten(value) + "' is not a Khepera line speed; give one of "
                    + KHEPERA_BAUDS + " (the robot's mode jumper)");
        }
    }

    private static int integer(String value) {
        long n = longInteger(value);
        if (n < Integer.MIN_VALUE || n > Integer.MAX_VALUE) {
            throw new TypeConversionException("'" + shorten(value) + "' is too large; give a smaller whole number");
        }
        return (int) n;
    }

    private static long longInteger(String value) {
        String t = value.strip();
        if (!t.matches("[+-]?+\\d{1,19}+")) {
            throw new TypeConversionException("'" + shorten(value)
                    + "' is not a whole decimal number; write it like 42");
        }
        try {
            return Long.parseLong(t);
        } catch (NumberFormatException e) {
            throw new TypeConversionException("'" + shorten(value) + "' is too large; give a whole number below "
                    + Long.MAX_VALUE);
        }
    }

    private static String shorten(String s) {
        return s.length() <= 40 ? s : s.substring(0, 37) + "...";
    }
}
