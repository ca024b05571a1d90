package org.kheperasim.sim.commandlog;

/** A command log that does not belong to the run it is replayed as, or does not fit it: says where. */
public final class ReplayMismatchException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** @param message what the log says against what the run was asked to be */
    public ReplayMismatchException(String message) {
        super(message);
    }
}
