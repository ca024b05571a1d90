package org.kheperasim.sim.grade.platform;

import java.util.List;
import java.util.Map;
import org.kheperasim.sim.grade.JsonValues;
import org.kheperasim.sim.grade.ReportFiles;

/**
 * Writes the platforms' JSON from maps (in their order), lists, strings, numbers and booleans, the way
 * the grade report writes {@code results.json} ({@link JsonValues#quote}: every control character
 * escaped); a number has at most 2 decimals, as the report's.
 */
final class JsonText {
    private JsonText() {
    }

    /**
     * @param value a map, list, string, number, boolean or null @return it as JSON, an entry of a list or map per line
     */
    static String of(Object value) {
        StringBuilder sb = new StringBuilder();
        write(value, "", sb);
        return sb.append('\n').toString();
    }

    /** @param value as {@link #of} @return it as JSON on one line */
    static String line(Object value) {
        StringBuilder sb = new StringBuilder();
        write(value, null, sb);
        return sb.toString();
    }

    private static void write(Object v, String indent, StringBuilder sb) {
        String inner = indent == null ? null : indent + "  ";
        if (v == null) {
            sb.append("null");
        } else if (v instanceof String s) {
            sb.append(JsonValues.quote(s));
        } else if (v instanceof Boolean b) {
            sb.append(b);
        } else if (v instanceof Integer || v instanceof Long) {
            sb.append(v);
        } else if (v instanceof Number n) {
            sb.append(ReportFiles.num(n.doubleValue()));
        } else if (v instanceof Map<?, ?> m) {
            sb.append('{');
            boolean first = true;
            for (Map.Entry<?, ?> e : m.entrySet()) {
                sb.append(first ? "" : ",").append(inner == null ? (first ? "" : " ") : "\n" + inner);
                sb.append(JsonValues.quote((String) e.getKey())).append(": ");
                write(e.getValue(), inner, sb);
                first = false;
            }
            sb.append(m.isEmpty() || inner == null ? "" : "\n" + indent).append('}');
        } else if (v instanceof List<?> l) {
            sb.append('[');
            for (int i = 0; i < l.size(); i++) {
                sb.append(i > 0 ? "," : "").append(inner == null ? (i > 0 ? " " : "") : "\n" + inner);
                write(l.get(i), inner, sb);
            }
            sb.append(l.isEmpty() || inner == null ? "" : "\n" + indent).append(']');
        } else {
            throw new IllegalArgumentException("no JSON for " + v.getClass().getName());
        }
    }
}
