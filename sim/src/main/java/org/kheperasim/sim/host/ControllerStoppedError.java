package org.kheperasim.sim.host;

/**
 * Thrown into a controller's thread to unwind it when the simulator stops it (end of the run,
 * the Stop button, or a controller that hung). An {@link Error}, so a controller's
 * {@code catch (InterruptedException e)} or {@code catch (Exception e)} does not swallow it.
 */
public final class ControllerStoppedError extends Error {
    /** @param message why the controller is being stopped */
    public ControllerStoppedError(String message) {
        super(message, null, false, false);
    }
}
