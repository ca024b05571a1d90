package org.kheperasim.sim.grade;

import java.util.Locale;

/** How one graded run ended, as the report names it. */
public enum RunStatus {
    /** The run went to its end (the controller finished or was stopped at the time limit). */
    OK("ok"),
    /**
     * The submission did not compile, holds no controller class, or could not be prepared (past a limit on
     * what a hand-in holds, see {@code SubmissionLimits}; the detail says which).
     */
    COMPILE_FAILED("failed to compile"),
    /** The student's folder is empty, or holds no {@code .java} or {@code .class} file. */
    NOTHING_HANDED_IN("nothing handed in"),
    /** The controller threw. */
    THREW("threw"),
    /** The controller stopped making API calls, or the run did not end within the wall-clock limit. */
    HUNG("hung"),
    /** The controller allocated without bound, or the child JVM ran out of heap. */
    EXCEEDED_MEMORY("exceeded memory"),
    /** The controller broke a containment rule (System.exit, a forbidden call; docs/controller-rules.md). */
    BROKE_RULE("broke a rule"),
    /**
     * The run's own result differed from the replay of its command log (or its log did not fit the
     * run) in both makings of it, its JVM having ended normally each time: the grader cannot tell a
     * fault of the simulator's replay from a forged result, so it names the difference (what, and
     * where) instead of a cause, and scores the replay. Not ranked until a person has looked (and worth a
     * bug report: docs/grading.md, "Verdicts").
     */
    DIVERGED("differs from its replay"),
    /**
     * Evidence that something other than the simulator wrote the run's result: a result that is not
     * the simulator's JSON; a result that differs from the replay, or a log that does not fit the run,
     * from a JVM that ended with an exit status the simulator never gives; a JVM that ended with
     * success without handing its result over. Not ranked.
     */
    TAMPERED("tampered"),
    /** The run could not be made for another reason (the message says which). */
    ERROR("error");

    private final String label;

    RunStatus(String label) {
        this.label = label;
    }

    /** @return how the report shows it, e.g. {@code failed to compile} */
    public String label() {
        return label;
    }

    /** @return the CSV/JSON word, e.g. {@code compile_failed} */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * @param word a {@link #word()}
     * @return the status
     * @throws IllegalArgumentException if it names none
     */
    public static RunStatus ofWord(String word) {
        return valueOf(word.toUpperCase(Locale.ROOT));
    }
}
