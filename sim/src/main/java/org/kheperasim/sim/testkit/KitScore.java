package org.kheperasim.sim.testkit;

import java.util.List;

/**
 * The score of an arena's tasks, as {@code khepera-sim run} prints it.
 *
 * @param parts each task's part, in the arena's order
 * @param points the points earned
 * @param max the points there are
 */
public record KitScore(List<Part> parts, double points, double max) {
    /**
     * @param task the task as the arena file states it
     * @param fraction how much of it was done, 0..1
     * @param points points earned
     * @param max its points
     * @param detail what was counted
     */
    public record Part(String task, double fraction, double points, double max, String detail) {
    }

    static KitScore of(org.kheperasim.sim.task.Score s) {
        return new KitScore(s.parts().stream()
                .map(p -> new Part(p.task(), p.fraction(), p.points(), p.max(), p.detail())).toList(),
                s.points(), s.max());
    }
}
