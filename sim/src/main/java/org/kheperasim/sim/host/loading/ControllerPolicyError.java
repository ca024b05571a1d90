package org.kheperasim.sim.host.loading;

/**
 * A controller class makes a call the simulator does not allow controller code to make (files,
 * network, processes, native code, class loaders, reflection, the simulator's own classes). Thrown
 * when the class is loaded; the message names the call, the student's source line and the fix.
 */
public final class ControllerPolicyError extends LinkageError {
    private static final long serialVersionUID = 1L;

    /** @param message what was refused, where, and what to do */
    public ControllerPolicyError(String message) {
        super(message);
    }
}
