package org.kheperasim.sim.host;

/** Where a controller is in its life. */
public enum ControllerStatus {
    /** Constructed, not yet started. */
    NOT_STARTED,
    /** Running (or sleeping) in lockstep with the engine. */
    RUNNING,
    /** Its {@code run()} returned. */
    FINISHED,
    /** Its {@code run()} threw; the robot was stopped. */
    FAILED,
    /** It stopped making API calls; it was reported and stopped. */
    HUNG,
    /** The simulator stopped it (end of the run, or asked to). */
    STOPPED,
    /** It broke a rule of the simulator (called System.exit, waited forever, made a forbidden call); it was stopped. */
    BROKE_RULE,
    /** It allocated without bound; it was stopped and what it held was let go. */
    EXCEEDED_MEMORY;

    /** @return true once the controller no longer runs */
    public boolean ended() {
        return this != NOT_STARTED && this != RUNNING;
    }

    /** @return true when the controller ended by a fault of its own (the run then failed) */
    public boolean failed() {
        return this == FAILED || this == HUNG || this == BROKE_RULE || this == EXCEEDED_MEMORY;
    }
}
