package org.kheperasim.sim.arena;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

/**
 * One part of an arena's assignment, scored from 0 to 1 at the end of a run.
 *
 * <ul>
 *   <li>{@link Kind#VISIT}: enter every region named (a name may end in {@code *} for every region
 *       whose name starts so, e.g. {@code c*}); the score is the fraction entered by a robot's centre.
 *   <li>{@link Kind#DELIVER}: caps lying on the floor inside the first region named at the end; the
 *       score is how many there are over {@code count} (at most 1).
 *   <li>{@link Kind#REACH}: a robot's centre enters the region named; 1 or 0.
 * </ul>
 *
 * @param kind what to do
 * @param regions the region names or prefixes ({@code c*}) the task is about
 * @param count for DELIVER: how many caps make the full score (0 for the other kinds)
 */
public record Task(Kind kind, List<String> regions, int count) {
    /** What a task asks. */
    public enum Kind {
        /** enter every region named */
        VISIT,
        /** bring caps into a region */
        DELIVER,
        /** reach a region */
        REACH;

        /** @return the keyword in the arena file */
        public String keyword() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    private static final Pattern PATTERN = Pattern.compile("[A-Za-z0-9_-]+\\*?");

    /** @throws IllegalArgumentException for no region, a malformed name, or a count that does not fit the kind */
    public Task {
        regions = List.copyOf(regions);
        if (regions.isEmpty()) {
            throw new IllegalArgumentException("task " + kind.keyword() + " needs a region's name");
        }
        for (String r : regions) {
            if (!PATTERN.matcher(r).matches()) {
                throw new IllegalArgumentException("task region '" + r + "' is not a region name (letters, digits, '_',"
                        + " '-'; a final '*' for every region whose name starts so)");
            }
        }
        if (kind != Kind.VISIT && regions.size() != 1) {
            throw new IllegalArgumentException("task " + kind.keyword() + " names one region, not " + regions.size());
        }
        if (kind == Kind.DELIVER ? count < 1 : count != 0) {
            throw new IllegalArgumentException(kind == Kind.DELIVER ? "task deliver needs a count of at least 1 cap"
                    : "task " + kind.keyword() + " takes no count");
        }
    }

    /**
     * @param arena the arena the task belongs to
     * @return the names of the arena's regions the task is about, in arena order
     */
    public List<String> matching(Arena arena) {
        List<String> out = new ArrayList<>();
        for (Region r : arena.regions()) {
            for (String p : regions) {
                if (p.endsWith("*") ? r.name().startsWith(p.substring(0, p.length() - 1)) : r.name().equals(p)) {
                    out.add(r.name());
                    break;
                }
            }
        }
        return out;
    }

    /** @return the task as its arena line, e.g. {@code task visit c*} or {@code task deliver target 5} */
    public String line() {
        return "task " + kind.keyword() + " " + String.join(" ", regions) + (kind == Kind.DELIVER ? " " + count : "");
    }
}
