package org.kheperasim.sim.host.loading;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.kheperasim.sim.host.loading.AllowlistEntry.ClassPattern;
import org.kheperasim.sim.host.loading.AllowlistEntry.Group;
import org.kheperasim.sim.host.loading.AllowlistEntry.Kind;
import org.kheperasim.sim.host.loading.AllowlistEntry.MemberItem;
import org.kheperasim.sim.host.loading.AllowlistEntry.PatternKind;

/**
 * Reads the allowlist's text (its format is described at the top of
 * {@code controller-allowlist.txt}). A malformed line is an {@link IllegalArgumentException} naming
 * the file's line: the list ships inside the simulator, so a mistake in it is a build failure, caught
 * by the tests, never a user's error.
 */
final class AllowlistParser {
    private static final String SEPARATOR = " -- ";

    private AllowlistParser() {
    }

    /**
     * @param name the file's name, for errors
     * @param text the file's text
     * @return its entries, in the file's order
     */
    static List<AllowlistEntry> parse(String name, String text) {
        List<AllowlistEntry> entries = new ArrayList<>();
        Group group = null;
        StringBuilder pending = null;
        int pendingLine = 0;
        String[] lines = text.split("\n", -1);
        for (int i = 0; i <= lines.length; i++) {
            String line = i < lines.length ? lines[i].stripTrailing() : "";
            boolean continues = !line.isEmpty() && Character.isWhitespace(line.charAt(0));
            if (continues && pending != null) {
                pending.append(' ').append(line.strip());
                continue;
            }
            if (pending != null) {
                entries.addAll(entry(name, pendingLine, pending.toString(), group));
                pending = null;
            }
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            if (continues) {
                throw error(name, i + 1, "a continuation line with no entry above it");
            }
            if (line.startsWith("==")) {
                group = group(line.substring(2).strip());
            } else {
                if (group == null) {
                    throw error(name, i + 1, "an entry before the first == heading");
                }
                pending = new StringBuilder(line);
                pendingLine = i + 1;
            }
        }
        return List.copyOf(entries);
    }

    private static Group group(String heading) {
        int colon = heading.indexOf(':');
        if (colon > 0) {
            String kind = heading.substring(0, colon).strip();
            String title = heading.substring(colon + 1).strip();
            if (kind.equals("bootstrap")) {
                return new Group(title, Kind.BOOTSTRAP);
            }
            if (kind.equals("refused")) {
                return new Group(title, Kind.REFUSED);
            }
        }
        return new Group(heading, Kind.ALLOWED);
    }

    /** One entry's text, joined from its lines: one entry per class a brace list names. */
    private static List<AllowlistEntry> entry(String file, int line, String text, Group group) {
        int separator = text.indexOf(SEPARATOR);
        if (separator < 0) {
            throw error(file, line, "no ' -- ' before the entry's reason: every entry says why");
        }
        String reason = text.substring(separator + SEPARATOR.length()).strip().replaceAll("\\s+", " ");
        List<String> tokens = new ArrayList<>(Arrays.asList(text.substring(0, separator).strip().split("\\s+")));
        String classes = tokens.remove(0);
        String mustExtend = null;
        if (!tokens.isEmpty() && tokens.get(0).equals("<")) {
            if (tokens.size() < 2) {
                throw error(file, line, "'<' names no class");
            }
            tokens.remove(0);
            mustExtend = tokens.remove(0);
        }
        if (reason.isEmpty()) {
            throw error(file, line, "an empty reason");
        }
        List<MemberItem> members = new ArrayList<>();
        for (String token : joinParameters(tokens)) {
            members.add(member(file, line, token));
        }
        List<AllowlistEntry> entries = new ArrayList<>();
        for (String c : expand(file, line, classes)) {
            entries.add(new AllowlistEntry(pattern(file, line, c, mustExtend), List.copyOf(members),
                    reason, group, line));
        }
        return entries;
    }

    /** Tokens split inside a parameter list ({@code new(java.io.Writer, boolean)}) joined again. */
    private static List<String> joinParameters(List<String> tokens) {
        List<String> joined = new ArrayList<>();
        StringBuilder open = null;
        for (String t : tokens) {
            if (open != null) {
                open.append(t);
                if (t.contains(")")) {
                    joined.add(open.toString());
                    open = null;
                }
            } else if (t.contains("(") && !t.contains(")")) {
                open = new StringBuilder(t);
            } else {
                joined.add(t);
            }
        }
        if (open != null) {
            joined.add(open.toString());
        }
        return joined;
    }

    /** {@code a.{B,C}.d} as {@code a.B.d} and {@code a.C.d} (each brace list in turn). */
    private static List<String> expand(String file, int line, String classes) {
        int open = classes.indexOf('{');
        if (open < 0) {
            return List.of(classes);
        }
        int close = classes.indexOf('}', open);
        if (close < 0) {
            throw error(file, line, "a '{' without '}' in " + classes);
        }
        List<String> names = new ArrayList<>();
        for (String part : classes.substring(open + 1, close).split(",")) {
            names.addAll(expand(file, line, classes.substring(0, open) + part.strip() + classes.substring(close + 1)));
        }
        return names;
    }

    private static ClassPattern pattern(String file, int line, String text, String mustExtend) {
        if (text.isEmpty() || text.contains("/") || text.contains("{")) {
            throw error(file, line, "not a class name or pattern: " + text);
        }
        if (text.endsWith(".**")) {
            return new ClassPattern(text, PatternKind.SUBPACKAGES, text.substring(0, text.length() - 2), mustExtend);
        }
        if (text.endsWith(".*")) {
            return new ClassPattern(text, PatternKind.PACKAGE, text.substring(0, text.length() - 1), mustExtend);
        }
        if (text.endsWith("*")) {
            return new ClassPattern(text, PatternKind.PREFIX, text.substring(0, text.length() - 1), mustExtend);
        }
        if (text.contains("*")) {
            throw error(file, line, "a '*' inside a class name: " + text);
        }
        return new ClassPattern(text, PatternKind.EXACT, text, mustExtend);
    }

    private static MemberItem member(String file, int line, String token) {
        boolean exclude = token.startsWith("-");
        String item = exclude ? token.substring(1) : token;
        List<String> parameters = null;
        int open = item.indexOf('(');
        if (open >= 0) {
            if (!item.endsWith(")")) {
                throw error(file, line, "a parameter list without ')': " + token);
            }
            String inside = item.substring(open + 1, item.length() - 1).strip();
            parameters = inside.isEmpty() ? List.of() : Arrays.stream(inside.split(",")).map(String::strip).toList();
            item = item.substring(0, open);
        }
        boolean prefix = item.length() > 1 && item.endsWith("*");
        String name = prefix ? item.substring(0, item.length() - 1) : item;
        if (name.equals("new")) {
            name = "<init>";
        }
        if (name.isEmpty() || (prefix && parameters != null) || (name.equals("*") && (parameters != null || exclude))
                || !name.equals("*") && !name.equals("<init>") && !Character.isJavaIdentifierStart(name.charAt(0))) {
            throw error(file, line, "not a member: " + token);
        }
        return new MemberItem(exclude, name, prefix, parameters);
    }

    private static IllegalArgumentException error(String file, int line, String what) {
        return new IllegalArgumentException(String.format(Locale.ROOT, "%s:%d: %s", file, line, what));
    }
}
