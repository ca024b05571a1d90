package org.kheperasim.sim.host;

/**
 * What a controller threw, as the simulator keeps it for the run's result and its windows: the
 * throwable's own description and stack, read once on the thread where it was thrown (the
 * controller's). The throwable's class is the student's, whose {@code toString()},
 * {@code getMessage()} and {@code getStackTrace()} may spin or throw; this copy's are the
 * simulator's, safe to ask on any thread.
 */
public final class ReportedFailure extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final String description;

    private ReportedFailure(String description, StackTraceElement[] trace) {
        super(description, null, false, true);
        this.description = description;
        setStackTrace(trace);
    }

    /**
     * @param e what the controller threw
     * @return its copy: {@code e.toString()} and {@code e.getStackTrace()}, or its class's name (and no stack) where
     *     asking it threw
     */
    static ReportedFailure of(Throwable e) {
        if (e instanceof ReportedFailure r) {
            return r;
        }
        String description;
        try {
            description = String.valueOf(e);
        } catch (RuntimeException | Error unreadable) {
            description = ControllerFailures.unreadable(e, unreadable);
        }
        StackTraceElement[] trace;
        try {
            trace = e.getStackTrace().clone();
        } catch (RuntimeException | Error unreadable) {
            trace = new StackTraceElement[0];
        }
        return new ReportedFailure(description, trace);
    }

    @Override
    public String toString() {
        return description;
    }
}
