package org.kheperasim.testing;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.opentest4j.AssertionFailedError;

/**
 * The message of a failed assertion about a run, for a student to read in the test report: a sentence
 * saying what went wrong, then what was expected, what happened and at what simulated time, which run it
 * was, and where its trace is (saved now, so it can be watched in the simulator's window).
 *
 * <pre>
 * MyController never entered region 'goal'.
 *   expected: to enter region 'goal' (x 1000.0..1219.2 mm, y 1000.0..1219.2 mm)
 *   happened: it did not in the 60.000 s the run lasted; nearest 212.4 mm from it at 41.250 s; ended at
 *             (380.0, 610.2) mm heading 90.0 deg
 *   run:      MyController in goal-field, seed 1, settings defaults, 60.000 s simulated
 *   trace:    target/kheperasim-runs/MyControllerTest/reachesTheGoal/goal-field-MyController-seed1.trace
 *             (watch it in a browser: target/kheperasim-runs/.../goal-field-MyController-seed1.html;
 *             how to make it again: the .txt beside it)
 * </pre>
 * <p>In a message the happened line and the watch line are one line each; they are wrapped here.
 */
final class Failure {
    /** How the line naming the trace starts. */
    static final String TRACE_LINE = "\n  trace:    ";
    private final String headline;
    private final List<String> lines = new ArrayList<>();

    private Failure(String headline) {
        this.headline = headline;
    }

    /** @param headline a sentence: what went wrong @return a message to add to */
    static Failure of(String headline) {
        return new Failure(headline);
    }

    /** @param what what the test asked for @return this */
    Failure expected(String what) {
        lines.add("  expected: " + what);
        return this;
    }

    /** @param what what the run did, with its simulated times @return this */
    Failure happened(String what) {
        lines.add("  happened: " + what);
        return this;
    }

    /** @param what a hint for the student @return this */
    Failure hint(String what) {
        lines.add("  hint:     " + what);
        return this;
    }

    /**
     * Save the run's trace (if it is not yet saved in this test's folder) and throw.
     *
     * @param run the run the assertion was about
     * @return never: it throws
     */
    AssertionFailedError raise(Run run) {
        StringBuilder s = new StringBuilder(headline);
        lines.forEach(l -> s.append('\n').append(l));
        s.append("\n  run:      ").append(describe(run));
        s.append(TRACE_LINE).append(trace(run));
        throw new AssertionFailedError(s.toString());
    }

    private static String describe(Run run) {
        String who = run.robots().size() == 1 ? run.robot().name() : run.robots().size() + " robots";
        String recorded = run.recordedFrom().isPresent() ? " (recorded)" : "";
        return who + " in " + run.arena() + ", seed " + run.seed() + ", settings " + run.settings() + ", "
                + run.duration() + " simulated" + recorded;
    }

    /** Where the trace is: the recording itself, or the file saved for this test now. */
    private static String trace(Run run) {
        if (run.recordedFrom().isPresent()) {
            return RunSpec.shown(run.recordedFrom().get())
                    + "\n            (watch it: khepera-sim's window, File > Open recording)";
        }
        try {
            Path saved = run.saveTo(TestRuns.folderNow());
            return RunSpec.shown(saved) + "\n            (watch it in a browser: " + RunSpec.shown(RunFiles.page(saved))
                    + "; how to make it again: the .txt beside it)";
        } catch (RuntimeException e) {
            return "not saved (" + e.getMessage() + "); make the run again with: " + run.commandLine();
        }
    }
}
