package org.kheperasim.sim.host;

/** Gives tests in other packages the package-private stop announcements of {@link SimClock}. */
public final class SimClockTestHooks {
    private SimClockTestHooks() {
    }

    /** @see SimClock#stopRequested() */
    public static void stopRequested() {
        SimClock.stopRequested();
    }

    /** @see SimClock#stopSettled() */
    public static void stopSettled() {
        SimClock.stopSettled();
    }
}
