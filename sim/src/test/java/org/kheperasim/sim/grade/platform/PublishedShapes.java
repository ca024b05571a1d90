package org.kheperasim.sim.grade.platform;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Collectors;
import org.kheperasim.sim.grade.JsonValues;

/**
 * The platforms' published examples (test resources, each naming its source) read as shapes: every
 * field's path ({@code tests[].max_score}) and the JSON types it takes there.
 */
final class PublishedShapes {
    private PublishedShapes() {
    }

    /** @param resource a {@code .jsonc} in {@code platforms/} @return its JSON value, comments stripped */
    static Object example(String resource) {
        String text;
        try (InputStream in = PublishedShapes.class.getResourceAsStream("/platforms/" + resource)) {
            text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        // Comments after values (none of the examples' strings holds "//"); Gradescope's ".926" is 0.926.
        String json = text.lines().map(l -> l.replaceFirst("\\s*//.*$", "")).collect(Collectors.joining("\n"))
                .replace(": .", ": 0.");
        return JsonValues.parse(json);
    }

    /** @param value a parsed JSON value @return each path in it and the types it takes there */
    static Map<String, Set<String>> shape(Object value) {
        Map<String, Set<String>> out = new TreeMap<>();
        walk(value, "", out);
        return out;
    }

    private static void walk(Object v, String path, Map<String, Set<String>> out) {
        out.computeIfAbsent(path, p -> new TreeSet<>()).add(type(v));
        if (v instanceof Map<?, ?> m) {
            for (Map.Entry<?, ?> e : m.entrySet()) {
                walk(e.getValue(), path + (path.isEmpty() ? "" : ".") + e.getKey(), out);
            }
        } else if (v instanceof List<?> l) {
            for (Object o : l) {
                walk(o, path + "[]", out);
            }
        }
    }

    static String type(Object v) {
        return v == null ? "null" : v instanceof String ? "string" : v instanceof Number ? "number" : v instanceof Boolean
                ? "boolean" : v instanceof Map ? "object" : "array";
    }

    /**
     * @param ours      our file's shape
     * @param published the published example's
     * @param free      paths under which the platform takes anything (e.g. {@code extra_data})
     * @return every path of ours the example lacks, or where ours has a type the example's has not, one line each
     */
    static List<String> differences(Map<String, Set<String>> ours, Map<String, Set<String>> published, Set<String> free) {
        return ours.entrySet().stream().filter(e -> free.stream().noneMatch(f -> e.getKey().startsWith(f + ".")))
                .filter(e -> !published.containsKey(e.getKey()) || !published.get(e.getKey()).containsAll(e.getValue()))
                .map(e -> e.getKey() + " " + e.getValue() + " (published: " + published.get(e.getKey()) + ")").toList();
    }
}
