package org.kheperasim.link.fuzz;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Ways to damage a text the way files get damaged: tokens swapped for numbers at and beyond every
 * edge, lines dropped, repeated or swapped, odd characters, line ends of every kind, truncation.
 * Starting from valid texts, a few of these make inputs that get past a reader's first checks.
 */
public final class Mutations {

    /** Numbers and near-numbers at the edges of what readers expect. */
    public static final List<String> EDGE_NUMBERS = List.of("0", "-0", "0.0", "1", "-1", "+1", ".5", "5.", "1e3", "1E-3",
            "1e308", "1e309", "-1e309", "4.9e-324", "1e-400", "2147483647", "2147483648", "-2147483649",
            "9223372036854775807", "9223372036854775808", "-9223372036854775808", "100000", "1e5", "1219.2", "360", "361",
            "-360", "720", "NaN", "nan", "Infinity", "-Infinity", "inf", "0x10", "0x1p10", "1d", "1f", "1_000", "1,5", "١٢",
            "", "-", "+", ".", "e", "1e", "1.2.3", "00000000000000000000000000001", "9".repeat(45), "1e-99999", "3600000",
            "1000000", "999999", "1000001", "60000", "50", "51", "500", "10000", "10001", "25000000", "1000", "1001");

    /** Odd characters: controls, line ends, a byte-order mark, non-ASCII letters, a lone surrogate. */
    public static final List<String> ODD_CHARS = List.of("\u0000", "\t", "\r", "\n", "\r\n", "\u000b", "\u000c", "\u0085",
            "\u2028", "\u00a0", "\ufeff", "\u00e9", "\u0130", "\ud800", "#", ",", "=", "@", " ", "  ", "\\", "\"", "'");

    private Mutations() {
    }

    /**
     * @param r random source
     * @param list a list
     * @return one element of it
     */
    public static <T> T pick(SplittableRandom r, List<T> list) {
        return list.get(r.nextInt(list.size()));
    }

    /** @return a number: mostly ordinary in {@code [lo, hi]}, sometimes an edge number */
    public static String number(SplittableRandom r, double lo, double hi) {
        int k = r.nextInt(10);
        if (k == 0) {
            return pick(r, EDGE_NUMBERS);
        }
        double d = lo + r.nextDouble() * (hi - lo);
        if (k < 4) {
            return Long.toString(Math.round(d));
        }
        if (k < 6) {
            return Double.toString(d);
        }
        return String.format(java.util.Locale.ROOT, "%.2f", d);
    }

    /**
     * Damages a text with 1 to {@code maxEdits} random edits.
     *
     * @param r random source
     * @param text a (usually valid) text
     * @param words words of the format (keywords), to put in odd places
     * @param maxEdits most edits
     * @return the damaged text
     */
    public static String damage(SplittableRandom r, String text, List<String> words, int maxEdits) {
        List<String> lines = new ArrayList<>(Arrays.asList(text.split("\n", -1)));
        int edits = 1 + r.nextInt(maxEdits);
        for (int e = 0; e < edits; e++) {
            if (lines.isEmpty()) {
                lines.add("");
            }
            int i = r.nextInt(lines.size());
            String line = lines.get(i);
            switch (r.nextInt(12)) {
                case 0, 1, 2 -> lines.set(i, replaceToken(r, line, pick(r, EDGE_NUMBERS)));
                case 3 -> lines.set(i, replaceToken(r, line, pick(r, words)));
                case 4 -> lines.remove(i);
                case 5 -> {
                    int copies = r.nextInt(8) == 0 ? 1 + r.nextInt(2000) : 1 + r.nextInt(3);
                    for (int c = 0; c < copies; c++) {
                        lines.add(i, line);
                    }
                }
                case 6 -> {
                    int j = r.nextInt(lines.size());
                    lines.set(i, lines.get(j));
                    lines.set(j, line);
                }
                case 7 -> lines.set(i, insert(r, line, pick(r, ODD_CHARS)));
                case 8 -> lines.set(i, line.isEmpty() ? line : line.substring(0, r.nextInt(line.length())));
                case 9 -> lines.add(i, pick(r, words) + " " + number(r, -10, 2000) + " " + number(r, -10, 2000));
                case 10 -> lines.set(i, insertToken(r, line, r.nextBoolean() ? pick(r, words) : pick(r, EDGE_NUMBERS)));
                default -> lines.set(i, dropToken(r, line));
            }
        }
        String out = String.join(r.nextInt(20) == 0 ? "\r\n" : "\n", lines);
        if (r.nextInt(20) == 0) {
            out = out.substring(0, r.nextInt(out.length() + 1));
        }
        return out;
    }

    private static String[] tokens(String line) {
        return line.strip().isEmpty() ? new String[0] : line.strip().split("[ \\t]+");
    }

    static String replaceToken(SplittableRandom r, String line, String with) {
        String[] t = tokens(line);
        if (t.length == 0) {
            return with;
        }
        t[r.nextInt(t.length)] = with;
        return String.join(" ", t);
    }

    static String insertToken(SplittableRandom r, String line, String token) {
        List<String> t = new ArrayList<>(Arrays.asList(tokens(line)));
        t.add(r.nextInt(t.size() + 1), token);
        return String.join(" ", t);
    }

    static String dropToken(SplittableRandom r, String line) {
        List<String> t = new ArrayList<>(Arrays.asList(tokens(line)));
        if (!t.isEmpty()) {
            t.remove(r.nextInt(t.size()));
        }
        return String.join(" ", t);
    }

    static String insert(SplittableRandom r, String line, String what) {
        int at = r.nextInt(line.length() + 1);
        return line.substring(0, at) + what + line.substring(at);
    }
}
