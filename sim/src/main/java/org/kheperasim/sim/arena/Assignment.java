package org.kheperasim.sim.arena;

import java.util.List;

/**
 * What an arena asks of a run: its tasks and its time limit ({@code task} and {@code time-limit}
 * lines). Scoring only: the simulation never looks at it, and {@link ArenaFormat#sha256} leaves it
 * out, so adding a task to an arena changes no trace.
 *
 * @param tasks            the tasks, in file order
 * @param timeLimitSeconds simulated seconds a run gets; 0 when the arena sets none
 */
public record Assignment(List<Task> tasks, double timeLimitSeconds) {

    /** No tasks, no time limit. */
    public static final Assignment NONE = new Assignment(List.of(), 0);
    /** Longest time limit, simulated seconds (a day). */
    public static final double MAX_TIME_LIMIT_SECONDS = 86_400;
    /** Most task lines in one arena. */
    public static final int MAX_TASKS = 100;

    /** Copies the list and checks the time limit. */
    public Assignment {
        tasks = List.copyOf(tasks);
        if (tasks.size() > MAX_TASKS) {
            throw new IllegalArgumentException("an arena may have at most " + MAX_TASKS + " task lines");
        }
        if (!(timeLimitSeconds >= 0 && timeLimitSeconds <= MAX_TIME_LIMIT_SECONDS)) {
            throw new IllegalArgumentException("time-limit is " + Numbers.brief(timeLimitSeconds)
                    + " s; give simulated seconds, more than 0 and at most " + Numbers.brief(MAX_TIME_LIMIT_SECONDS));
        }
    }

    /** @return true when there is at least one task */
    public boolean hasTasks() {
        return !tasks.isEmpty();
    }

    /** @return the points of every task together */
    public double maxPoints() {
        return tasks.stream().mapToDouble(Task::points).sum();
    }

    /**
     * @param fallback simulated seconds when the arena sets no limit
     * @return the time limit, or {@code fallback}
     */
    public double secondsOr(double fallback) {
        return timeLimitSeconds > 0 ? timeLimitSeconds : fallback;
    }
}
