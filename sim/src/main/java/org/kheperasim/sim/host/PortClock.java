package org.kheperasim.sim.host;

/**
 * The time behind a {@link SimulatedRobotPort}: a controller's clock, which charges each API call
 * its simulated time and keeps the lockstep (a thread-style controller's {@link ControllerClock},
 * or a step controller's {@link StepHost}).
 */
interface PortClock {
    /** Every API call starts here. */
    void enter();

    /** Every API call ends here: it costs its simulated time. */
    void leave();

    /** @return the controller's simulated time now, ns */
    long now();

    /** Let {@code nanos} of simulated time pass for the controller. */
    void sleepNanos(long nanos) throws InterruptedException;

    /** A line for the run's console from the controller. */
    void say(ConsoleLine.Kind kind, String text);
}
