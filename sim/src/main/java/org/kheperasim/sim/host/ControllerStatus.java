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
    STOPPED;

    /** @return true once the controller no longer runs */
    public boolean ended() {
        return this != NOT_STARTED && this != RUNNING;
    }
}
