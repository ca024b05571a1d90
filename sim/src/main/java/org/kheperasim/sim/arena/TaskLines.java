package org.kheperasim.sim.arena;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.BiFunction;

/**
 * Reads the {@code task} lines of an arena file (for {@link ArenaParser}) and checks, once the
 * whole file is read, that the regions they name exist. Errors are {@link IllegalArgumentException}s
 * whose message says what is wrong and the fix; the parser adds the file and line.
 */
final class TaskLines {
    static final String KINDS = "visit, cover, deliver, reach";
    private static final String VISIT = "task visit needs region names or prefixes ending in '*', e.g. 'task visit c*'"
            + " or 'task visit room_a room_b', optionally followed by 'points <n>'";
    private static final String COVER = "task cover needs the percent of the floor to cover, e.g. 'task cover 60',"
            + " optionally followed by 'points <n>'";
    private static final String DELIVER = "task deliver needs 'caps into <region>' or '<count> caps into <region>',"
            + " e.g. 'task deliver caps into target', optionally followed by 'points <n>'";
    private static final String REACH = "task reach needs one region's name, e.g. 'task reach goal',"
            + " optionally followed by 'points <n>'";

    private TaskLines() {
    }

    /**
     * @param t      the line's words, {@code t[0]} being {@code task}
     * @param number parses a word as a number, given what it is (for the error)
     * @return the task
     */
    static Task parse(String[] t, BiFunction<String, String, Double> number) {
        if (t.length < 2) {
            throw new IllegalArgumentException("task needs a kind (" + KINDS + "), e.g. 'task visit c*'");
        }
        List<String> words = new ArrayList<>(Arrays.asList(t).subList(2, t.length));
        double points = Task.DEFAULT_POINTS;
        int p = words.indexOf("points");
        if (p >= 0) {
            if (p != words.size() - 2) {
                throw new IllegalArgumentException("'points <n>' must end a task line, with one number after it");
            }
            points = number.apply(words.get(p + 1), "task points");
            words = words.subList(0, p);
        }
        return switch (t[1]) {
            case "visit" -> visit(words, points);
            case "cover" -> {
                if (words.size() != 1) {
                    throw new IllegalArgumentException(COVER + ", got " + words.size() + " values");
                }
                yield new Task.Cover(number.apply(words.get(0), "task cover percent"), points);
            }
            case "deliver" -> deliver(words, points, number);
            case "reach" -> {
                if (words.size() != 1 || !Region.NAME.matcher(words.get(0)).matches()) {
                    throw new IllegalArgumentException(REACH);
                }
                yield new Task.Reach(words.get(0), points);
            }
            default -> throw new IllegalArgumentException("unknown task '" + shorten(t[1])
                    + "'; the tasks are " + KINDS);
        };
    }

    private static Task visit(List<String> words, double points) {
        if (words.isEmpty() || words.size() > ArenaLimits.MAX_REGIONS) {
            throw new IllegalArgumentException(VISIT);
        }
        for (String w : words) {
            String name = w.endsWith("*") ? w.substring(0, w.length() - 1) : w;
            if (!(name.isEmpty() && w.equals("*")) && !Region.NAME.matcher(name).matches()) {
                throw new IllegalArgumentException("task visit: '" + shorten(w)
                        + "' is not a region name or prefix*; " + VISIT);
            }
        }
        return new Task.Visit(words, points);
    }

    private static Task deliver(List<String> words, double points, BiFunction<String, String, Double> number) {
        int count = 0;
        List<String> rest = words;
        if (words.size() == 4) {
            double n = number.apply(words.get(0), "task deliver count");
            if (n != StrictMath.rint(n) || n < 1 || n > ArenaLimits.MAX_CAPS) {
                throw new IllegalArgumentException("task deliver count is " + Numbers.brief(n)
                        + "; give a whole number of caps from 1 to " + ArenaLimits.MAX_CAPS);
            }
            count = (int) n;
            rest = words.subList(1, 4);
        }
        if (rest.size() != 3 || !rest.get(0).equals("caps") || !rest.get(1).equals("into")
                || !Region.NAME.matcher(rest.get(2)).matches()) {
            throw new IllegalArgumentException(DELIVER);
        }
        return new Task.Deliver(count, rest.get(2), points);
    }

    /**
     * Checks a task against the whole arena.
     *
     * @return null when it is fine, else what is wrong and the fix
     */
    static String check(Task task, List<Region> regions, int caps) {
        List<String> names = regions.stream().map(Region::name).toList();
        String known = names.isEmpty() ? "the arena has no regions; add a 'region <name> x1 y1 x2 y2' line"
                : "the regions are " + shorten(String.join(", ", names), 200);
        if (task instanceof Task.Visit v) {
            for (String p : v.patterns()) {
                if (names.stream().noneMatch(n -> Task.Visit.matches(p, n))) {
                    return "task visit: no region "
                            + (p.endsWith("*") ? "starts with '" + p.substring(0, p.length() - 1) + "'"
                            : "is named '" + p + "'") + "; " + known;
                }
            }
        } else if (task instanceof Task.Deliver d) {
            if (!names.contains(d.region())) {
                return "task deliver: no region is named '" + d.region() + "'; " + known;
            }
            if (caps == 0) {
                return "task deliver: the arena has no caps; add 'cap <x> <y>' lines or remove the task";
            }
            if (d.count() > caps) {
                return "task deliver asks for " + d.count() + " caps but the arena has " + caps
                        + "; ask for at most " + caps;
            }
        } else if (task instanceof Task.Reach r && !names.contains(r.region())) {
            return "task reach: no region is named '" + r.region() + "'; " + known;
        }
        return null;
    }

    private static String shorten(String s) {
        return shorten(s, 40);
    }

    private static String shorten(String s, int max) {
        return s.length() <= max ? s : s.substring(0, max - 3) + "...";
    }
}
