package org.kheperasim.sim.eval;

import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.task.Score;

/**
 * What a job came to: its run's result and score, or why it could not be run.
 *
 * @param job the job
 * @param result the run's result, or null when it could not be run
 * @param score the run's score by its arena's tasks, or null (no tasks, or not run)
 * @param error why the job could not be run (a bad arena, controller or setting: one line naming the
 *     thing and the fix), or null
 */
public record Outcome(Job job, RunResult result, Score score, String error) {
    /** @return true when the run was made and every controller in it ended normally */
    public boolean ok() {
        return error == null && result.robots().stream().noneMatch(r -> r.status().failed());
    }
}
