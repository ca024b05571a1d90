package org.kheperasim.sim.web;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.task.RunFacts;

/**
 * What a run's page says besides its samples: a title, the controllers that failed, and what the
 * run counted for its score at the end. A trace records none of these; whoever ran the run does.
 *
 * @param title      the page's heading, e.g. {@code WallFollower in maze · seed 1}; empty: the page
 *                   makes one from the trace's header
 * @param failures   the controllers that failed, marked on the timeline
 * @param finalFacts what the run counted for its score (regions entered with their exact times, the
 *                   floor covered, caps per region), or null when only the samples are known: the
 *                   page then scores regions and caps from the samples and cannot show floor coverage
 */
public record RunOutcome(String title, List<Failure> failures, RunFacts finalFacts) {

    /**
     * A controller that failed.
     *
     * @param robot   the robot's index, from 0
     * @param seconds simulated time it failed at, s; NaN when not known (the page then marks it at the
     *                time its robot's controller was seen failed, or at the end)
     * @param status  how it failed, as the run reports it: {@code failed} (threw), {@code hung},
     *                {@code broke_rule}, {@code exceeded_memory}
     * @param message what it threw or why it was stopped, with the student's line when known
     */
    public record Failure(int robot, double seconds, String status, String message) {
        /** Keeps the texts non-null. */
        public Failure {
            status = status == null ? "failed" : status;
            message = message == null ? "" : message;
        }
    }

    /** Copies the list; a null title is empty. */
    public RunOutcome {
        title = title == null ? "" : title;
        failures = List.copyOf(failures);
    }

    /** @return nothing known beyond the samples */
    public static RunOutcome none() {
        return new RunOutcome("", List.of(), null);
    }

    /**
     * @param result a finished run
     * @return its title, its failed controllers (times not known: a recorder's console lines give them)
     *     and its facts
     */
    public static RunOutcome of(RunResult result) {
        List<Failure> failures = new ArrayList<>();
        for (int i = 0; i < result.robots().size(); i++) {
            RunResult.RobotResult r = result.robots().get(i);
            if (r.status().failed()) {
                failures.add(new Failure(i, Double.NaN, r.status().name().toLowerCase(Locale.ROOT), r.failure()));
            }
        }
        String controller = result.controller().substring(result.controller().lastIndexOf('.') + 1);
        return new RunOutcome(controller + " in " + result.arena() + " · seed " + result.seed(), failures,
                RunFacts.of(result));
    }

    /** @param newTitle the page's heading @return this outcome with that title */
    public RunOutcome withTitle(String newTitle) {
        return new RunOutcome(newTitle, failures, finalFacts);
    }

    /** @param f one more failure @return this outcome with it */
    public RunOutcome withFailure(Failure f) {
        List<Failure> all = new ArrayList<>(failures);
        all.add(f);
        return new RunOutcome(title, all, finalFacts);
    }
}
