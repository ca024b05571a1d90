package org.kheperasim.sim.host.loading;

import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.host.SimClock;

/** A simulation clock for tests: records what the rewritten hooks ask of it. */
final class FakeClock implements SimClock.Clock {
    /** The simulated time the clock starts at. */
    static final long START_NANOS = 5_000_000_000L;
    /** The simulated epoch milliseconds at {@link #START_NANOS}. */
    static final long EPOCH_MILLIS = 946_684_800_000L;

    /** What {@link #checkpoint()} throws once a stop is asked for. */
    static final class Stop extends Error {
        Stop() {
            super("controller stopped");
        }
    }

    private final List<Long> sleeps = new ArrayList<>();
    private long nanos = START_NANOS;
    private int pauses;
    private volatile boolean stop;

    @Override
    public synchronized void sleepNanos(long duration) {
        sleeps.add(duration);
        nanos += duration;
    }

    @Override
    public synchronized long nanoTime() {
        return nanos;
    }

    @Override
    public synchronized long currentTimeMillis() {
        return EPOCH_MILLIS + (nanos - START_NANOS) / 1_000_000;
    }

    @Override
    public synchronized void pause() {
        pauses++;
    }

    @Override
    public void checkpoint() {
        if (stop) {
            throw new Stop();
        }
    }

    @Override
    public boolean onControllerThread() {
        return true;
    }

    @Override
    public void brokeRule(String what) {
        rules.add(what);
    }

    @Override
    public boolean adopt(Thread thread) {
        adopted.add(thread);
        return false;
    }

    /** The rules broken so far, as reported. */
    final List<String> rules = new java.util.concurrent.CopyOnWriteArrayList<>();
    /** The threads adopted so far. */
    final List<Thread> adopted = new java.util.concurrent.CopyOnWriteArrayList<>();

    /** From now on {@link #checkpoint()} throws {@link Stop}. */
    void requestStop() {
        stop = true;
    }

    /** @return the simulated nanoseconds of each sleep, in order */
    synchronized List<Long> sleeps() {
        return List.copyOf(sleeps);
    }

    /** @return how many yield or spin-wait hints arrived */
    synchronized int pauses() {
        return pauses;
    }
}
