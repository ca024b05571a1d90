package org.kheperasim.sim.engine.robot;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The shape of a robot file, before its meaning: the small part of YAML the format uses (see
 * {@code docs/robot-files.md}). Top-level {@code key: value} lines and sections ({@code key:} alone,
 * then lines indented by two spaces); a section's list items start {@code - } (a map of keys, its
 * further keys indented by four spaces, or one flow list {@code - [1, 2, 3]}); a section's key
 * alone ({@code values:}) takes flow-list items indented by four spaces; {@code #} starts a
 * comment. Anything else is refused with its line.
 */
final class RobotFileLines {

    /** One {@code key: value} or list item, with the line it came from. */
    static final class Entry {
        final String key;
        final String value;
        final int line;
        /** A section's keys, in file order. */
        final Map<String, Entry> keys = new LinkedHashMap<>();
        /** A section's list items: each a map of keys, or a flow list held in {@link #value}. */
        final List<Entry> items = new ArrayList<>();

        Entry(String key, String value, int line) {
            this.key = key;
            this.value = value;
            this.line = line;
        }
    }

    private final String source;

    private RobotFileLines(String source) {
        this.source = source;
    }

    /**
     * @param source the file's name, for errors
     * @param text the file's text
     * @return the root: the top-level keys
     * @throws RobotFileException naming the first line that has no place in the format
     */
    static Entry read(String source, String text) {
        return new RobotFileLines(source).parse(text);
    }

    private Entry parse(String text) {
        Entry root = new Entry("", "", 0);
        Entry section = null;
        Entry item = null;
        Entry sub = null;
        String[] lines = text.split("\n", -1);
        for (int n = 0; n < lines.length; n++) {
            int lineNo = n + 1;
            String raw = lines[n].endsWith("\r") ? lines[n].substring(0, lines[n].length() - 1) : lines[n];
            if (raw.indexOf('\t') >= 0) {
                throw error(lineNo, "a tab; indent with spaces (two per level)");
            }
            String line = stripComment(raw);
            if (line.isBlank()) {
                continue;
            }
            int indent = 0;
            while (line.charAt(indent) == ' ') {
                indent++;
            }
            String body = line.strip();
            if (indent == 0) {
                Entry e = keyValue(body, lineNo);
                put(root, e);
                section = e.value.isEmpty() ? e : null;
                item = null;
                sub = null;
            } else if (indent == 2 && section != null && body.startsWith("- ")) {
                String rest = body.substring(2).strip();
                if (rest.startsWith("[")) {
                    section.items.add(new Entry("-", rest, lineNo));
                    item = null;
                    sub = null;
                } else {
                    item = new Entry("-", "", lineNo);
                    section.items.add(item);
                    put(item, keyValue(rest, lineNo));
                    sub = null;
                }
            } else if (indent == 2 && section != null) {
                Entry e = keyValue(body, lineNo);
                put(section, e);
                item = null;
                sub = e.value.isEmpty() ? e : null;
            } else if (indent == 4 && sub != null && body.startsWith("- [")) {
                sub.items.add(new Entry("-", body.substring(2).strip(), lineNo));
            } else if (indent == 4 && item != null) {
                put(item, keyValue(body, lineNo));
            } else {
                throw error(lineNo, "indented " + indent
                        + " spaces here; top-level keys start the line, a section's keys"
                        + " take 2 spaces, a list item's further keys 4");
            }
        }
        return root;
    }

    private static String stripComment(String line) {
        int hash = line.indexOf('#');
        return hash < 0 ? line : line.substring(0, hash);
    }

    private Entry keyValue(String body, int lineNo) {
        int colon = body.indexOf(':');
        if (colon <= 0) {
            throw error(lineNo, "'" + body + "' is not 'key: value'; write e.g. 'radius: 27.5'");
        }
        String key = body.substring(0, colon).strip();
        if (!key.matches("[a-z_]+")) {
            throw error(lineNo, "key '" + key + "' is not a key; keys are lower-case words joined by '_'");
        }
        return new Entry(key, body.substring(colon + 1).strip(), lineNo);
    }

    private void put(Entry into, Entry e) {
        if (into.keys.containsKey(e.key)) {
            throw error(e.line, "'" + e.key + "' is given twice (first on line " + into.keys.get(e.key).line
                    + "); keep one");
        }
        into.keys.put(e.key, e);
    }

    private RobotFileException error(int line, String what) {
        return new RobotFileException(source, line, what);
    }
}
