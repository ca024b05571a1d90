package org.kheperasim.link.robot;

/**
 * Thrown into a controller that calls the robot API after the run has stopped, so that a controller
 * stuck in a loop that never checks its stop flag (the Appendix's {@code findwall()}) still ends.
 * An Error, so the usual {@code catch (Exception e)} does not swallow it.
 */
public final class ControllerStoppedError extends Error {
    ControllerStoppedError() {
        super("the robot was stopped; the controller is being ended", null, false, false);
    }
}
