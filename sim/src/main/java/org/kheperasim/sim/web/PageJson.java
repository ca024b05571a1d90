package org.kheperasim.sim.web;

import java.util.Locale;
import org.kheperasim.sim.text.Shown;

/**
 * Writes the page's description of a run as a JavaScript object literal in JSON form, safe inside
 * an HTML {@code <script>} element: besides JSON's own escapes, {@code <}, {@code >}, {@code &} and
 * the two line separators JavaScript refuses in strings are written as {@code \\uXXXX}, so no text
 * from a run (a controller's exception message, an arena's name) can end the script or the page.
 */
final class PageJson {
    private final StringBuilder out = new StringBuilder(4096);
    private boolean first = true;

    PageJson begin() {
        comma();
        out.append('{');
        first = true;
        return this;
    }

    PageJson begin(String key) {
        key(key);
        out.append('{');
        first = true;
        return this;
    }

    PageJson end() {
        out.append('}');
        first = false;
        return this;
    }

    PageJson array(String key) {
        key(key);
        out.append('[');
        first = true;
        return this;
    }

    PageJson array() {
        comma();
        out.append('[');
        first = true;
        return this;
    }

    PageJson endArray() {
        out.append(']');
        first = false;
        return this;
    }

    PageJson put(String key, String value) {
        key(key);
        string(value);
        return this;
    }

    PageJson put(String key, double value) {
        key(key);
        number(value);
        return this;
    }

    PageJson put(String key, boolean value) {
        key(key);
        out.append(value);
        return this;
    }

    /** An array element. */
    PageJson value(double v) {
        comma();
        number(v);
        return this;
    }

    /** An array element. */
    PageJson value(String s) {
        comma();
        string(s);
        return this;
    }

    @Override
    public String toString() {
        return out.toString();
    }

    private void key(String key) {
        comma();
        string(key);
        out.append(':');
    }

    private void comma() {
        if (!first) {
            out.append(',');
        }
        first = false;
    }

    /** A number as JSON writes it: whole numbers without a point, others with at most 4 decimals; NaN as null. */
    private void number(double v) {
        if (Double.isNaN(v) || Double.isInfinite(v)) {
            out.append("null");
        } else if (v == StrictMath.rint(v) && StrictMath.abs(v) < 1e15) {
            out.append((long) v);
        } else {
            String s = String.format(Locale.ROOT, "%.4f", v);
            out.append(s.replaceFirst("0+$", ""));
        }
    }

    private void string(String s) {
        if (s == null) {
            out.append("null");
            return;
        }
        out.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> out.append("\\\"");
                case '\\' -> out.append("\\\\");
                case '\n' -> out.append("\\n");
                case '\r' -> out.append("\\r");
                case '\t' -> out.append("\\t");
                default -> {
                    if (Shown.isControl(c) || c == '<' || c == '>' || c == '&') {  // isControl: also U+2028/9, bidi, C1
                        out.append(String.format(Locale.ROOT, "\\u%04x", (int) c));
                    } else {
                        out.append(c);
                    }
                }
            }
        }
        out.append('"');
    }
}
