package org.kheperasim.sim.engine;

/**
 * What drives a robot: its controller, running in lockstep with the engine. The engine asks each
 * tick whether the driver needs to run, and if so lets it run for that tick's stretch of simulated
 * time; the driver returns only when it needs time beyond the stretch (or has ended).
 */
public interface RobotDriver {
    /** @return the simulated time the driver next needs to run at, ns; {@link Long#MAX_VALUE} once it has ended */
    long wakeNanos();

    /**
     * Run the controller from its wake time up to (not including) {@code endNanos}.
     *
     * @param startNanos the tick's start, ns
     * @param endNanos the tick's end, ns
     */
    void runSlice(long startNanos, long endNanos);
}
