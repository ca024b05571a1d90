package org.kheperasim.sim.arena;

import java.util.ArrayList;
import java.util.List;

/**
 * Reads an arena file's assignment lines for {@link ArenaParser}:
 * {@code task visit <region>...}, {@code task deliver <region> <caps>}, {@code task reach <region>}
 * and {@code time-limit <seconds>}. Messages say what is wrong and the fix; the parser adds the
 * file and line.
 */
final class AssignmentLines {
    private final List<Task> tasks = new ArrayList<>();
    private final List<Integer> taskLines = new ArrayList<>();
    private double timeLimit;
    private int timeLimitLine;

    /** @param t the line's tokens, {@code task} first @param line its number */
    void task(String[] t, int line) {
        if (tasks.size() >= ArenaLimits.MAX_TASKS) {
            throw new IllegalArgumentException("more than " + ArenaLimits.MAX_TASKS + " tasks; an arena sets at most that many");
        }
        if (t.length < 3) {
            throw new IllegalArgumentException("task needs a kind and a region: 'task visit c*', 'task deliver target 5'"
                    + " or 'task reach goal'");
        }
        Task.Kind kind = switch (t[1]) {
            case "visit" -> Task.Kind.VISIT;
            case "deliver" -> Task.Kind.DELIVER;
            case "reach" -> Task.Kind.REACH;
            default -> throw new IllegalArgumentException("unknown task '" + shorten(t[1]) + "'; tasks are visit, deliver and reach");
        };
        List<String> regions = new ArrayList<>(List.of(t).subList(2, t.length));
        int count = 0;
        if (kind == Task.Kind.DELIVER) {
            if (regions.size() != 2) {
                throw new IllegalArgumentException("task deliver needs a region and a number of caps, e.g. 'task deliver target 5'");
            }
            try {
                count = Integer.parseInt(regions.remove(1));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("task deliver's number of caps is not a whole number; e.g. 'task deliver target 5'", e);
            }
        }
        tasks.add(new Task(kind, regions, count));
        taskLines.add(line);
    }

    /** @param t the line's tokens @param line its number @param seconds the parsed number */
    void timeLimit(String[] t, int line, double seconds) {
        if (timeLimitLine != 0) {
            throw new IllegalArgumentException("a second 'time-limit' line (the first is line " + timeLimitLine + "); keep one");
        }
        if (!(seconds > 0 && seconds <= ArenaLimits.MAX_TIME_LIMIT_S)) {
            throw new IllegalArgumentException("time-limit " + shorten(t[1]) + " s is out of range; give 1 to "
                    + (long) ArenaLimits.MAX_TIME_LIMIT_S + " s");
        }
        timeLimit = seconds;
        timeLimitLine = line;
    }

    /** @return the assignment read */
    Assignment assignment() {
        return tasks.isEmpty() && timeLimit == 0 ? Assignment.NONE : new Assignment(tasks, timeLimit);
    }

    /**
     * @param check builds the arena with one task only, to find the line a task's fault is on
     * @return the line of the first task the arena refuses, or 0
     */
    int lineOfBadTask(java.util.function.Function<Assignment, Arena> check) {
        for (int i = 0; i < tasks.size(); i++) {
            try {
                check.apply(new Assignment(List.of(tasks.get(i)), 0));
            } catch (IllegalArgumentException e) {
                return taskLines.get(i);
            }
        }
        return 0;
    }

    private static String shorten(String token) {
        return token.length() <= 40 ? token : token.substring(0, 37) + "...";
    }
}
