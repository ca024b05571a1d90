package org.kheperasim.sim.arena;

import java.util.regex.Pattern;

/** The numbers of an arena file's lines, read strictly: each failure names the file, the line and the fix. */
final class TokenNumbers {
    /** Possessive quantifiers: a long run of digits cannot make the match backtrack. */
    static final Pattern NUMBER = Pattern.compile("[+-]?+(\\d++(\\.\\d*+)?+|\\.\\d++)([eE][+-]?+\\d++)?+");
    private static final Pattern NOT_FINITE = Pattern.compile("[+-]?(nan|inf|infinity)", Pattern.CASE_INSENSITIVE);

    private final String source;

    TokenNumbers(String source) {
        this.source = source;
    }

    /** Parses {@code t[from..]} as exactly {@code fields.length} numbers of line {@code line}. */
    double[] numbers(String[] t, int from, String usage, int line, String... fields) {
        int count = t.length - from;
        if (count != fields.length) {
            throw new ArenaFormatException(source, line,
                    usage + ", got " + count + (count == 1 ? " value" : " values"));
        }
        double[] n = new double[count];
        for (int i = 0; i < count; i++) {
            n[i] = number(t[from + i], t[0] + " " + fields[i], line);
        }
        return n;
    }

    /** @return the token as a finite number; {@code what} names it in the error */
    double number(String token, String what, int line) {
        if (token.length() > ArenaLimits.MAX_NUMBER_CHARS) {
            throw new ArenaFormatException(source, line, what + " is '" + shorten(token) + "', longer than "
                    + ArenaLimits.MAX_NUMBER_CHARS + " characters; write a decimal number such as 12.5");
        }
        if (NUMBER.matcher(token).matches()) {
            double d = Double.parseDouble(token);
            if (Double.isFinite(d)) {
                return d;
            }
            throw new ArenaFormatException(source, line, what + " is '" + shorten(token)
                    + "', too large to be a number of mm; give a finite number");
        }
        if (NOT_FINITE.matcher(token).matches()) {
            throw new ArenaFormatException(source, line,
                    what + " is '" + token + "'; give a finite number such as 12.5");
        }
        throw new ArenaFormatException(source, line, what + " is '" + shorten(token)
                + "', not a number; write a decimal number such as 12.5");
    }

    /** A token as quoted in a message: at most 40 characters. */
    static String shorten(String token) {
        return token.length() <= 40 ? token : token.substring(0, 37) + "...";
    }
}
