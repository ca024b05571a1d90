package org.kheperasim.sim.host;

import java.util.concurrent.TimeUnit;

/**
 * Tuning of a controller host that is not part of the simulation's result: the hang timeout, and
 * the random real-time delays the determinism tests inject at hand-offs.
 */
public record HostOptions(long hangTimeoutNanos, int jitterMaxMicros) {
    /** Defaults: a controller is hung after 5 s of real time without an API call; no jitter. */
    public static HostOptions defaults() {
        return new HostOptions(TimeUnit.SECONDS.toNanos(5), 0);
    }

    /** @param micros largest random real-time delay injected at hand-offs (tests of determinism) */
    public HostOptions withJitter(int micros) {
        return new HostOptions(hangTimeoutNanos, micros);
    }

    /** @param nanos real time without an API call after which a controller is hung */
    public HostOptions withHangTimeout(long nanos) {
        return new HostOptions(nanos, jitterMaxMicros);
    }
}
