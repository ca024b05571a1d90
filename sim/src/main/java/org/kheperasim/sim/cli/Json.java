package org.kheperasim.sim.cli;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.Locale;
import java.util.Map;
import org.kheperasim.sim.text.Shown;

/** A minimal JSON writer for the run summary: a few flat values, objects and arrays. */
final class Json {
    private static final MathContext SIGNIFICANT = new MathContext(9);
    private final StringBuilder out = new StringBuilder();
    private boolean first = true;

    Json begin() {
        out.append('{');
        first = true;
        return this;
    }

    Json end() {
        out.append('}');
        first = false;
        return this;
    }

    Json beginArray(String key) {
        key(key);
        out.append('[');
        first = true;
        return this;
    }

    Json endArray() {
        out.append(']');
        first = false;
        return this;
    }

    Json beginObject(String key) {
        key(key);
        return begin();
    }

    Json element() {
        comma();
        return begin();
    }

    Json put(String key, String value) {
        key(key);
        if (value == null) {
            out.append("null");
        } else {
            string(value);
        }
        return this;
    }

    Json put(String key, long value) {
        key(key);
        out.append(value);
        return this;
    }

    Json put(String key, double value) {
        key(key);
        if (Double.isFinite(value)) {
            out.append(new BigDecimal(value).round(SIGNIFICANT).stripTrailingZeros().toPlainString());
        } else {
            out.append("null");
        }
        return this;
    }

    Json put(String key, Map<String, ? extends Number> values) {
        beginObject(key);
        values.forEach((k, v) -> {
            if (v instanceof Integer || v instanceof Long) {
                put(k, v.longValue());
            } else {
                put(k, v.doubleValue());
            }
        });
        return end();
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

    private void string(String s) {
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
                    if (Shown.isControl(c)) { // C0, and what a terminal or renderer acts on
                        out.append(String.format(Locale.ROOT, "\\u%04x", (int) c));
                    } else {
                        out.append(c);
                    }
                }
            }
        }
        out.append('"');
    }

    @Override
    public String toString() {
        return out.toString();
    }
}
