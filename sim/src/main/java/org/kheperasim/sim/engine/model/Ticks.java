package org.kheperasim.sim.engine.model;

/** The engine's tick, the step of simulated time everything in the engine moves by. */
public final class Ticks {
    /** The tick: 1 ms of simulated time, ns. */
    public static final long NANOS = 1_000_000L;

    private Ticks() {
    }

    /**
     * @param nanos a simulated time, ns
     * @return the first tick at or after it; for {@link Long#MAX_VALUE} (never), a tick no run reaches
     *     that can still be added to without overflow
     */
    public static long ceil(long nanos) {
        return nanos == Long.MAX_VALUE ? Long.MAX_VALUE / 2 : -Math.floorDiv(-nanos, NANOS);
    }
}
