package org.kheperasim.sim.engine;

/**
 * What drives a robot: its controller, running in lockstep with the engine. Each tick the engine
 * asks every driver whether it needs to run; if so it grants the driver the rest of the tick as its
 * slice and hands it the turn (see {@link Engine#advance()}).
 */
public interface RobotDriver {
    /** @return the simulated time the driver next needs to run at, ns; {@link Long#MAX_VALUE} once it has ended */
    long wakeNanos();

    /**
     * The driver may run up to (not including) this simulated time before it must give the turn
     * back.
     *
     * @param limitNanos the end of the current tick, ns
     */
    void grant(long limitNanos);
}
