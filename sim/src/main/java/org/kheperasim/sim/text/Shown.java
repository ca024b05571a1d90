package org.kheperasim.sim.text;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Student-derived text as a person is shown it: every character a terminal, a spreadsheet or a
 * bidirectional renderer would act on instead of showing (C0 controls, DEL, C1 controls, the Unicode
 * bidi embeddings, overrides, isolates and marks, the line and paragraph separators) is written as a
 * visible escape: {@code \e} (ESC), {@code \n}, {@code \r}, {@code \t}, {@code \x07} (another
 * control up to U+00FF), {@code \u202e} (any other). In a file ({@link #line}: {@code report.txt},
 * {@code results.csv}) a backslash is written {@code \\}, so {@link #unescape} gives the text back
 * exactly; on a screen ({@link #visible}, {@link #lines}: the terminal, the window's console, an error
 * line) a backslash stays one, so that a Windows path reads as typed. Applied where text is written
 * for a person, never to what the simulator computes with.
 */
public final class Shown {
    /** The first characters that make a spreadsheet evaluate a cell (OWASP's CSV injection rule), and {@code '}. */
    private static final String FORMULA_START = "=+-@\t\r'";

    private Shown() {
    }

    /**
     * @param c a UTF-16 char (the characters this class escapes are all in the BMP)
     * @return whether a terminal or renderer would act on it instead of showing it
     */
    public static boolean isControl(char c) {
        return c < 0x20 || (c >= 0x7f && c <= 0x9f)
                || c == 0x061c || c == 0x200e || c == 0x200f           // Arabic letter mark, LRM, RLM
                || (c >= 0x2028 && c <= 0x202e)                      // line/paragraph separators, embeddings, overrides
                || (c >= 0x2066 && c <= 0x2069);                       // isolates
    }

    /**
     * @param s text, or null
     * @return it on one line, every control character (line ends too) and backslash escaped; {@code "null"} for null
     */
    public static String line(String s) {
        if (s == null) {
            return "null";
        }
        if (!needsEscape(s)) {
            return s;
        }
        StringBuilder out = new StringBuilder(s.length() + 16);
        for (int i = 0; i < s.length(); i++) {
            escape(s.charAt(i), out);
        }
        return out.toString();
    }

    /**
     * For an error message, which names the user's own files: as {@link #line}, but a backslash stays
     * one (a Windows path reads as typed), so this is not always reversible.
     *
     * @param s text, or null
     * @return it on one line, every control character escaped
     */
    public static String visible(String s) {
        if (s == null) {
            return "null";
        }
        StringBuilder out = new StringBuilder(s.length() + 16);
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '\\') {
                out.append(c);
            } else {
                escape(c, out);
            }
        }
        return out.toString();
    }

    /**
     * @param s text that may span lines ({@code \n}, {@code \r\n}); null reads as {@code "null"}
     * @return its lines, each escaped as {@link #visible} escapes (for a person reading, a backslash stays
     *     one); the tabs that start a line (a stack trace's indentation) become four spaces each; at least
     *     one line
     */
    public static List<String> lines(String s) {
        List<String> out = new ArrayList<>();
        String text = s == null ? "null" : s;
        int start = 0;
        while (true) {
            int nl = text.indexOf('\n', start);
            int end = nl < 0 ? text.length() : nl;
            int cut = nl > start && text.charAt(nl - 1) == '\r' ? end - 1 : end;
            int indent = start;
            while (indent < cut && text.charAt(indent) == '\t') {
                indent++;
            }
            out.add("    ".repeat(indent - start) + visible(text.substring(indent, cut)));
            if (nl < 0) {
                return out;
            }
            start = nl + 1;
        }
    }

    /**
     * @param prefix what each line starts with, saying whose text it is (escaped here too)
     * @param s      text that may span lines
     * @return every line of {@code s} (as {@link #lines}) after the prefix, joined with {@code \n}: no line of
     *     it can pose as another's
     */
    public static String stamped(String prefix, String s) {
        String p = visible(prefix);
        StringBuilder out = new StringBuilder();
        for (String l : lines(s)) {
            out.append(out.length() == 0 ? "" : "\n").append(p).append(l);
        }
        return out.toString();
    }

    /**
     * A text cell of a CSV file: escaped as {@link #line} escapes (so it is one line), then, when it
     * starts with {@code =}, {@code +}, {@code -}, {@code @} (or {@code '}), given a leading {@code '}
     * so that no spreadsheet evaluates it; quoted (RFC 4180) when it holds a comma or a quote. Only for
     * text: the numbers a program writes are written as numbers.
     *
     * @param s the text
     * @return the cell
     */
    public static String csvCell(String s) {
        String v = line(s);
        if (!v.isEmpty() && FORMULA_START.indexOf(v.charAt(0)) >= 0) {
            v = "'" + v;
        }
        return v.contains(",") || v.contains("\"") ? "\"" + v.replace("\"", "\"\"") + "\"" : v;
    }

    /**
     * @param cell a CSV cell's text, unquoted, as {@link #csvCell} wrote it
     * @return the text it was made from
     */
    public static String fromCsvCell(String cell) {
        return unescape(cell.startsWith("'") ? cell.substring(1) : cell);
    }

    /**
     * @param s text written by {@link #line}
     * @return the text it was made from
     * @throws IllegalArgumentException for an escape this class does not write
     */
    public static String unescape(String s) {
        if (s.indexOf('\\') < 0) {
            return s;
        }
        StringBuilder out = new StringBuilder(s.length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c != '\\') {
                out.append(c);
                continue;
            }
            char e = i + 1 < s.length() ? s.charAt(i + 1) : 0;
            int hex = e == 'x' ? 2 : e == 'u' ? 4 : 0;
            switch (e) {
                case '\\' -> out.append('\\');
                case 'e' -> out.append('\u001b');
                case 'n' -> out.append('\n');
                case 'r' -> out.append('\r');
                case 't' -> out.append('\t');
                case 'x', 'u' -> {
                    if (i + 2 + hex > s.length()) {
                        throw new IllegalArgumentException("a cut escape at " + i + " in " + line(s));
                    }
                    out.append((char) Integer.parseInt(s.substring(i + 2, i + 2 + hex), 16));
                    i += hex;
                }
                default -> throw new IllegalArgumentException("not an escape at " + i + " in " + line(s));
            }
            i++;
        }
        return out.toString();
    }

    private static boolean needsEscape(String s) {
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '\\' || isControl(c)) {
                return true;
            }
        }
        return false;
    }

    private static void escape(char c, StringBuilder out) {
        switch (c) {
            case '\\' -> out.append("\\\\");
            case '\u001b' -> out.append("\\e");
            case '\n' -> out.append("\\n");
            case '\r' -> out.append("\\r");
            case '\t' -> out.append("\\t");
            default -> {
                if (!isControl(c)) {
                    out.append(c);
                } else if (c <= 0xff) {
                    out.append(String.format(Locale.ROOT, "\\x%02x", (int) c));
                } else {
                    out.append(String.format(Locale.ROOT, "\\u%04x", (int) c));
                }
            }
        }
    }
}
