package org.kheperasim.sim.task;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Region;
import org.kheperasim.sim.arena.Task;
import org.kheperasim.sim.engine.Engine;

/**
 * A run's score against its arena's assignment: the points of each task, earned in proportion to
 * the fraction of it done, and their sum.
 *
 * @param parts  one per task, in the arena's order
 * @param points the points earned, the sum of the parts
 * @param max    the points of every task together
 */
public record Score(List<Part> parts, double points, double max) {

    /**
     * One task's share.
     *
     * @param task     the task line, as written in the arena file
     * @param fraction how much of it was done, 0..1
     * @param points   points earned: fraction × the task's points
     * @param max      the task's points
     * @param detail   what was counted, e.g. {@code 17/25 regions} or {@code reached at 41.3 s}
     */
    public record Part(String task, double fraction, double points, double max, String detail) {
    }

    /** Copies the list. */
    public Score {
        parts = List.copyOf(parts);
    }

    /**
     * Scores a run.
     *
     * @param arena the arena, with its assignment
     * @param facts what the run knows
     * @return the score (no parts, 0 of 0, when the arena has no tasks)
     */
    public static Score of(Arena arena, RunFacts facts) {
        List<Part> parts = new ArrayList<>();
        double sum = 0;
        double max = 0;
        for (Task t : arena.assignment().tasks()) {
            Part p = part(t, arena, facts);
            parts.add(p);
            sum += p.points();
            max += p.max();
        }
        return new Score(parts, sum, max);
    }

    /**
     * The live score, for the window: call on the thread that steps the engine, or while it is paused.
     *
     * @param engine the running engine (its arena, as edited so far, holds the assignment)
     * @return the score so far
     */
    public static Score live(Engine engine) {
        return of(engine.world().arena(), RunFacts.live(engine));
    }

    /** @return the points earned as a percentage of the maximum, 0..100 (0 when there is nothing to earn) */
    public double percent() {
        return max > 0 ? 100 * points / max : 0;
    }

    /** @return e.g. {@code 62.5/100 (visit c*: 15/25 regions; reach goal: not reached)} */
    public String summary() {
        StringBuilder s = new StringBuilder(String.format(Locale.ROOT, "%s/%s", number(points), number(max)));
        if (!parts.isEmpty()) {
            s.append(" (");
            for (int i = 0; i < parts.size(); i++) {
                Part p = parts.get(i);
                s.append(i > 0 ? "; " : "").append(p.task().replaceFirst("^task ", "")).append(": ").append(p.detail());
            }
            s.append(')');
        }
        return s.toString();
    }

    /** A number as a score shows it: at most two decimals, no trailing zeros. */
    public static String number(double d) {
        String s = String.format(Locale.ROOT, "%.2f", d);
        return s.contains(".") ? s.replaceFirst("\\.?0+$", "") : s;
    }

    private static Part part(Task t, Arena arena, RunFacts f) {
        double fraction;
        String detail;
        if (t instanceof Task.Visit v) {
            List<Region> regions = v.regions(arena);
            long in = regions.stream().filter(r -> f.regionsEntered().containsKey(r.name())).count();
            fraction = regions.isEmpty() ? 0 : (double) in / regions.size();
            detail = in + "/" + regions.size() + " regions";
        } else if (t instanceof Task.Cover c) {
            fraction = StrictMath.min(1, f.visitedPercent() / c.percent());
            detail = String.format(Locale.ROOT, "%.1f%% of %s%% of the floor", f.visitedPercent(), number(c.percent()));
        } else if (t instanceof Task.Deliver d) {
            int want = d.count() > 0 ? d.count() : f.caps();
            int in = f.capsInRegions().getOrDefault(d.region(), 0);
            fraction = want == 0 ? 0 : StrictMath.min(1, (double) in / want);
            detail = in + "/" + want + " caps";
        } else {
            Task.Reach r = (Task.Reach) t;
            Double at = f.regionsEntered().get(r.region());
            fraction = at == null ? 0 : 1;
            detail = at == null ? "not reached" : String.format(Locale.ROOT, "reached at %.1f s", at);
        }
        return new Part(t.line(), fraction, fraction * t.points(), t.points(), detail);
    }
}
