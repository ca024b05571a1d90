package org.kheperasim.testing;

import java.util.List;
import java.util.Locale;

/**
 * A run's score against its arena's assignment (the arena file's {@code task} lines; see the simulator's
 * docs/arena-format.md): the same score {@code khepera-sim run} prints and {@code grade} ranks by.
 *
 * @param tasks one per task, in the arena's order (empty when the arena sets no task)
 * @param points points earned, the sum of the tasks'
 * @param max points of every task together
 */
public record Score(List<TaskScore> tasks, double points, double max) {

    /**
     * Copies the list.
     *
     * @param tasks one per task, in the arena's order
     * @param points points earned
     * @param max points of every task together
     */
    public Score {
        tasks = List.copyOf(tasks);
    }

    /** @return the points earned as a percentage of the maximum, 0..100 (0 when there is nothing to earn) */
    public double percent() {
        return max > 0 ? 100 * points / max : 0;
    }

    /**
     * The score on a course's own scale, e.g. the 10 points an assignment is worth in its grade book.
     *
     * @param scale the points a full score is worth, more than 0
     * @return {@code scale} times the fraction earned (0 when the arena sets no task)
     */
    public double scaledTo(double scale) {
        if (!(scale > 0) || Double.isInfinite(scale)) {
            throw new IllegalArgumentException("a score's scale of " + scale + " points must be a number above 0");
        }
        return max > 0 ? scale * points / max : 0;
    }

    /**
     * @param taskStart how the task line starts, e.g. {@code task reach goal} or just {@code reach goal}
     * @return the first task whose line starts so
     * @throws IllegalArgumentException naming the arena's tasks when none does
     */
    public TaskScore task(String taskStart) {
        String want = taskStart.strip().startsWith("task ") ? taskStart.strip() : "task " + taskStart.strip();
        for (TaskScore t : tasks) {
            if (t.task().startsWith(want)) {
                return t;
            }
        }
        throw new IllegalArgumentException("no task starts with '" + want + "'; the arena's tasks are "
                + tasks.stream().map(TaskScore::task).toList());
    }

    /** @return e.g. {@code 60/100 (reach goal: reached at 41.3 s; deliver 2 caps into goal: 0/2 caps)} */
    @Override
    public String toString() {
        StringBuilder s = new StringBuilder(number(points) + "/" + number(max));
        if (!tasks.isEmpty()) {
            s.append(" (");
            for (int i = 0; i < tasks.size(); i++) {
                TaskScore t = tasks.get(i);
                s.append(i > 0 ? "; " : "").append(t.task().replaceFirst("^task ", "")).append(": ").append(t.detail());
            }
            s.append(')');
        }
        return s.toString();
    }

    static String number(double d) {
        String s = String.format(Locale.ROOT, "%.2f", d);
        return s.contains(".") ? s.replaceFirst("\\.?0+$", "") : s;
    }
}
