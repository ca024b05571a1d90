package org.kheperasim.testing;

import java.util.Optional;

/**
 * How a robot's controller ended.
 *
 * @param kind what happened
 * @param at simulated time it happened, when known (a fault's time; for {@link Kind#RAN_TO_THE_END} the run's end)
 * @param message what the simulator said: the exception, the rule broken, why it counted as hung; empty
 *     when it ended normally
 * @param where the student's source line it happened at, {@code MyController.java:42}, when known: the line that
 *     threw, or that made the forbidden call; empty otherwise (a hang names no line)
 */
public record Ending(Kind kind, Optional<SimTime> at, String message, Optional<String> where) {

    /** What a controller's end was. */
    public enum Kind {
        /** It was still running when the run's time was up (the simulator then stopped it): the usual end. */
        RAN_TO_THE_END,
        /** Its {@code run()} returned, or its {@code doWork()} loop ended itself. */
        RETURNED,
        /** It threw an exception it did not catch; the robot was stopped. */
        THREW,
        /** It stopped making API calls (an endless loop without a sensor read, a motor command or a sleep). */
        HUNG,
        /** It broke a rule of the simulator (System.exit, a forbidden call, a wait nothing can end). */
        BROKE_A_RULE,
        /** It allocated memory without bound. */
        OUT_OF_MEMORY,
        /** Not known: the run was read from a trace, which does not record it (run it again to know). */
        NOT_RECORDED
    }

    /**
     * Checks the parts are there.
     *
     * @param kind what happened
     * @param at simulated time it happened, when known
     * @param message what the simulator said; empty when it ended normally
     * @param where the student's source line, when known
     */
    public Ending {
        java.util.Objects.requireNonNull(kind, "kind");
        java.util.Objects.requireNonNull(at, "at");
        java.util.Objects.requireNonNull(message, "message");
        java.util.Objects.requireNonNull(where, "where");
    }

    /** @return true when the controller ran to the end of the run or returned by itself */
    public boolean normal() {
        return kind == Kind.RAN_TO_THE_END || kind == Kind.RETURNED;
    }

    /** @return e.g. {@code threw java.lang.ArithmeticException: / by zero at MyController.java:42, at 12.345 s} */
    @Override
    public String toString() {
        String what = switch (kind) {
            case RAN_TO_THE_END -> "ran to the end of the run";
            case RETURNED -> "returned by itself";
            case THREW, HUNG, BROKE_A_RULE, OUT_OF_MEMORY -> firstLine(message);
            case NOT_RECORDED -> "not recorded (a trace does not say how the controller ended)";
        };
        StringBuilder s = new StringBuilder(what);
        where.ifPresent(w -> s.append(" (").append(w).append(')'));
        if (!normal()) {
            at.ifPresent(t -> s.append(", at ").append(t));
        }
        return s.toString();
    }

    private static String firstLine(String text) {
        int nl = text.indexOf('\n');
        return nl < 0 ? text : text.substring(0, nl);
    }
}
