package org.kheperasim.sim.host;

import org.kheperasim.api.spi.ControllerException;

/**
 * Watches a controller being constructed: its constructor and the static initializers it runs
 * execute on the thread that builds the run (the command's, or the window's), before any watchdog
 * of the run exists. One that has not returned after the hang timeout is stopped at its next loop
 * checkpoint, and the run is refused with a message that says so, instead of hanging for ever.
 */
final class ConstructionWatch implements StepWatchdog.Watched {
    private final long deadline;
    private final Thread constructing = Thread.currentThread();
    private volatile boolean fired;

    private ConstructionWatch(long timeoutNanos) {
        this.deadline = System.nanoTime() + timeoutNanos;
    }

    /**
     * Construct a controller on the calling thread, watched.
     *
     * @param name the controller's name in messages
     * @param type its class
     * @param timeoutNanos real time the construction may take
     * @param make constructs it
     * @param <T> what is made
     * @return what {@code make} made
     * @throws ControllerException when the construction overran (what it threw when stopped is the cause)
     */
    static <T> T construct(String name, Class<?> type, long timeoutNanos, java.util.function.Supplier<T> make) {
        ConstructionWatch watch = start(timeoutNanos);
        T made;
        try {
            made = make.get();
        } catch (RuntimeException | Error e) {
            if (watch.fired()) {
                throw hung(name, type, timeoutNanos, e);
            }
            throw e;
        } finally {
            watch.end();
        }
        if (watch.fired()) {
            throw hung(name, type, timeoutNanos, null);
        }
        return made;
    }

    /**
     * Watch the construction the calling thread is about to make.
     *
     * @param timeoutNanos real time the construction may take
     * @return the watch, until {@link #end}
     */
    private static ConstructionWatch start(long timeoutNanos) {
        ConstructionWatch w = new ConstructionWatch(timeoutNanos);
        StepWatchdog.watch(w);
        return w;
    }

    private boolean ended;

    @Override
    public synchronized boolean overdue(long nowNanos) {
        // Under the watch's lock with end(): a construction that has just returned is not marked afterwards.
        if (fired || ended || nowNanos - deadline < 0) {
            return false;
        }
        fired = true;
        SimClock.stopConstructing(constructing);
        return true;
    }

    /** The construction has returned or thrown: no longer watched. */
    private void end() {
        StepWatchdog.unwatch(this);
        synchronized (this) {
            ended = true;
            if (fired) {
                SimClock.constructed(constructing);
            }
        }
    }

    /** @return true when the construction overran and was asked to stop */
    private boolean fired() {
        return fired;
    }

    /**
     * @param name the controller's name in messages
     * @param type its class
     * @param timeoutNanos the hang timeout
     * @param thrown what the construction threw when it was stopped, or null
     * @return the refusal of the run
     */
    private static ControllerException hung(String name, Class<?> type, long timeoutNanos, Throwable thrown) {
        return new ControllerException(String.format(java.util.Locale.ROOT, "controller %s (%s) was not constructed:"
                + " its constructor or a static initializer ran for %.1f s of real time without returning. Do not"
                + " loop or wait there: read the sensors and drive in run(), doWork() or step()", name, type.getName(),
                timeoutNanos / 1e9), thrown);
    }
}
