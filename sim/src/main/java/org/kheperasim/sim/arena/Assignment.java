package org.kheperasim.sim.arena;

import java.util.List;

/**
 * What an arena asks of a robot, as its {@code task} and {@code time-limit} lines say: the tasks
 * scored at the end of a run, and how long a run lasts unless told otherwise.
 *
 * @param tasks the tasks, in file order (none: the arena has no assignment)
 * @param timeLimitSeconds the assignment's time, simulated s; 0 when the arena gives none
 */
public record Assignment(List<Task> tasks, double timeLimitSeconds) {
    /** No assignment. */
    public static final Assignment NONE = new Assignment(List.of(), 0);

    /** @throws IllegalArgumentException for a negative or absurd time limit */
    public Assignment {
        tasks = List.copyOf(tasks);
        if (!(timeLimitSeconds >= 0 && timeLimitSeconds <= ArenaLimits.MAX_TIME_LIMIT_S)) {
            throw new IllegalArgumentException("time-limit " + timeLimitSeconds + " s is out of range; give 1 to "
                    + (long) ArenaLimits.MAX_TIME_LIMIT_S + " s");
        }
    }

    /** @return true when the arena sets tasks or a time limit */
    public boolean any() {
        return !tasks.isEmpty() || timeLimitSeconds > 0;
    }
}
