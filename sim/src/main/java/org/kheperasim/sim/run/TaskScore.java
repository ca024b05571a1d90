package org.kheperasim.sim.run;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Task;

/**
 * How well a run did one task of its arena's assignment.
 *
 * @param task the task's arena line, e.g. {@code task visit c*}
 * @param fraction 0 to 1
 * @param detail what was counted, e.g. {@code 24 of 25 regions}
 */
public record TaskScore(String task, double fraction, String detail) {

    /** @return the score in whole percent */
    public int percent() {
        return (int) StrictMath.floor(fraction * 100 + 1e-9);
    }

    /**
     * Scores every task of an arena's assignment.
     *
     * @param arena the arena as the run started (its assignment)
     * @param entered each region entered by a robot's centre, with the first time, s
     * @param capsInRegions for each region, the caps on the floor inside it now
     * @return one score per task, in file order (none without tasks)
     */
    public static List<TaskScore> score(Arena arena, Map<String, Double> entered, Map<String, Integer> capsInRegions) {
        double limit = arena.assignment().timeLimitSeconds();
        List<TaskScore> out = new ArrayList<>();
        for (Task t : arena.assignment().tasks()) {
            List<String> names = t.matching(arena);
            switch (t.kind()) {
                case VISIT -> {
                    long in = names.stream().filter(n -> within(entered.get(n), limit)).count();
                    out.add(new TaskScore(t.line(), names.isEmpty() ? 0 : (double) in / names.size(),
                            in + " of " + names.size() + " regions entered"));
                }
                case REACH -> {
                    Double at = entered.get(names.get(0));
                    boolean ok = within(at, limit);
                    out.add(new TaskScore(t.line(), ok ? 1 : 0, ok ? String.format(Locale.ROOT, "reached at %.1f s", at)
                            : "not reached"));
                }
                case DELIVER -> {
                    int caps = capsInRegions.getOrDefault(names.get(0), 0);
                    out.add(new TaskScore(t.line(), StrictMath.min(1.0, (double) caps / t.count()),
                            caps + " of " + t.count() + " caps in " + names.get(0)));
                }
                default -> throw new IllegalStateException("unknown task " + t.kind());
            }
        }
        return out;
    }

    /** @param scores a run's task scores @return their mean in whole percent (0 without tasks) */
    public static int total(List<TaskScore> scores) {
        if (scores.isEmpty()) {
            return 0;
        }
        double sum = 0;
        for (TaskScore s : scores) {
            sum += s.fraction;
        }
        return (int) StrictMath.floor(sum / scores.size() * 100 + 1e-9);
    }

    /** @param scores a run's task scores @return e.g. {@code score 96 % (task visit c*: 24 of 25 regions entered)} */
    public static String describe(List<TaskScore> scores) {
        StringBuilder b = new StringBuilder("score ").append(total(scores)).append(" %");
        String sep = " (";
        for (TaskScore s : scores) {
            b.append(sep).append(s.task).append(": ").append(s.detail);
            sep = "; ";
        }
        return scores.isEmpty() ? b.toString() : b.append(')').toString();
    }

    private static boolean within(Double at, double limit) {
        return at != null && (limit <= 0 || at <= limit);
    }
}
