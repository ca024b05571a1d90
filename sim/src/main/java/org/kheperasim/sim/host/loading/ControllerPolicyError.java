package org.kheperasim.sim.host.loading;

/**
 * A controller class uses something that the controller allowlist does not allow untrusted code to
 * use (files, the network, processes, reflection, the JVM's settings, thread pools, windows, the
 * simulator's own classes, and everything else not on the list). Thrown when the class is loaded;
 * the one-line message names the use, the student's source file and line, and the rule.
 */
public final class ControllerPolicyError extends LinkageError {
    private static final long serialVersionUID = 1L;

    /** @param message what was refused, where, and what to do */
    public ControllerPolicyError(String message) {
        super(message);
    }
}
