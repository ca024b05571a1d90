package org.kheperasim.sim.host;

import java.util.concurrent.TimeUnit;

/**
 * Tuning of a run that is not part of the simulation's result: the hang timeout, the random
 * real-time delays the determinism tests inject at hand-offs, and the threads the engine may use.
 *
 * @param hangTimeoutNanos real time without an API call after which a controller is hung, ns
 * @param jitterMaxMicros largest random real-time delay injected at hand-offs, µs (0: none)
 * @param engineThreads threads the engine's step may use for a large swarm: 1 or 2, or 0 for the
 *     default ({@link #engineThreads()})
 */
public record HostOptions(long hangTimeoutNanos, int jitterMaxMicros, int engineThreads) {
    /** The system property that sets the default of {@link #engineThreads()}. */
    public static final String ENGINE_THREADS_PROPERTY = "kheperasim.engineThreads";

    /**
     * Defaults: a controller is hung after 5 s of real time without an API call; no jitter; the default engine threads.
     */
    public static HostOptions defaults() {
        return new HostOptions(TimeUnit.SECONDS.toNanos(5), 0, 0);
    }

    /** @param micros largest random real-time delay injected at hand-offs (tests of determinism) */
    public HostOptions withJitter(int micros) {
        return new HostOptions(hangTimeoutNanos, micros, engineThreads);
    }

    /** @param nanos real time without an API call after which a controller is hung */
    public HostOptions withHangTimeout(long nanos) {
        return new HostOptions(nanos, jitterMaxMicros, engineThreads);
    }

    /**
     * @param threads threads the engine's step may use, 1 or 2 (a run computes the same trace with either)
     * @return these options with that many
     */
    public HostOptions withEngineThreads(int threads) {
        if (threads < 1 || threads > 2) {
            throw new IllegalArgumentException("engine threads: 1 or 2, not " + threads);
        }
        return new HostOptions(hangTimeoutNanos, jitterMaxMicros, threads);
    }

    /**
     * @return the threads the engine's step uses: as set, else the system property
     *     {@value #ENGINE_THREADS_PROPERTY}, else 2 where the JVM has two cores or more, 1 otherwise
     */
    @Override
    public int engineThreads() {
        if (engineThreads > 0) {
            return engineThreads;
        }
        String p = System.getProperty(ENGINE_THREADS_PROPERTY);
        if (p != null) {
            try {
                return StrictMath.max(1, StrictMath.min(2, Integer.parseInt(p.strip())));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("-D" + ENGINE_THREADS_PROPERTY + "=" + p + ": give 1 or 2", e);
            }
        }
        return Runtime.getRuntime().availableProcessors() >= 2 ? 2 : 1;
    }
}
