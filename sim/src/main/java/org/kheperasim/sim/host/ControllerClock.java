package org.kheperasim.sim.host;

import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.kheperasim.sim.engine.RobotDriver;

/**
 * A controller's own simulated clock. Each API call costs {@code api.callCostUs} of simulated time
 * (that is how a busy loop makes time pass), {@code Thread.sleep(ms)} costs exactly {@code ms}, and
 * computing between calls costs nothing. The engine lets the controller run through one tick's
 * stretch of simulated time at a time ({@link #grant}); a call that reaches past it steps the world
 * forward on the controller's own thread until some controller must run again.
 *
 * <p>The class loader rewrites a controller's {@code Thread.sleep}, {@code System.nanoTime} and
 * friends onto this clock (through {@link SimClock}); calls from any other thread fall through to
 * the real ones.
 */
final class ControllerClock implements SimClock.Clock {
    /**
     * Robot time starts at the Appendix controller's creation date, 2001-07-27T11:06:00Z, so
     * currentTimeMillis looks plausible (a literal: parsing the date would load the java.time
     * formatters at every start).
     */
    static final long EPOCH_MILLIS = 996_231_960_000L;

    /** The heap is looked at every 16 API calls (a few nanoseconds each, on average). */
    private static final int HEAP_LOOK_MASK = 15;

    private final ControllerHost host;
    private final long apiCostNanos;
    private final int jitterMaxMicros;
    private long apiCalls;
    // Only the thread holding the turn touches these (the turn is volatile).
    private long now;
    private long limit;
    private long wake;

    ControllerClock(ControllerHost host, long apiCostNanos, int jitterMaxMicros) {
        this.host = host;
        this.apiCostNanos = apiCostNanos;
        this.jitterMaxMicros = jitterMaxMicros;
    }

    /** @return the controller's simulated time now, ns */
    long now() {
        return now;
    }

    /** @return when the controller next needs to run, ns */
    long wake() {
        return wake;
    }

    /** The engine grants the controller simulated time up to {@code limitNanos}. */
    void grant(long limitNanos) {
        limit = limitNanos;
    }

    /** @return API calls made so far; read without synchronisation by the watchdog */
    long apiCalls() {
        return apiCalls;
    }

    /** Every API call starts here: the lockstep check. */
    void enter() {
        Thread t = Thread.currentThread();
        if (t != host.thread()) {
            if (host.status() == ControllerStatus.NOT_STARTED) {
                return; // the controller's constructor looking around: free, no time passes
            }
            throw new IllegalStateException("the robot API was called from thread '" + t.getName() + "', not from"
                    + " the controller's own thread; in the simulator only the controller thread may use it"
                    + " (that keeps runs deterministic)");
        }
        host.checkStop();
        if ((++apiCalls & HEAP_LOOK_MASK) == 0) {
            lookAtHeap();
        }
        if (now >= limit) {
            yieldTurn();
        }
    }

    /** A controller that allocates without bound is stopped before the heap runs out. */
    private void lookAtHeap() {
        String full = HeapWatch.pressed();
        if (full != null) {
            host.exceededMemory(full);
            host.checkStop();
        }
    }

    /** Every API call ends here: it costs its simulated time. */
    void leave() {
        now += apiCostNanos;
    }

    /** The controller's slice is used up: step the world on this thread until someone must run. */
    private void yieldTurn() {
        wake = now;
        jitter();
        Lockstep lockstep = host.lockstep();
        RobotDriver next;
        try {
            next = lockstep.engine().advance();
        } catch (RuntimeException | Error e) {
            lockstep.engineFailed(e);
            next = null;
        }
        if (next == host) {
            return;
        }
        lockstep.passTo(next);
        lockstep.turn().await(host.seat());
        host.checkStop();
    }

    /** Random real-time delays at hand-offs, for the determinism tests. */
    private void jitter() {
        if (jitterMaxMicros > 0 && ThreadLocalRandom.current().nextInt(8) == 0) {
            LockSupport.parkNanos(ThreadLocalRandom.current().nextLong(jitterMaxMicros * 1000L + 1));
        }
    }

    @Override
    public void sleepNanos(long nanos) throws InterruptedException {
        if (Thread.currentThread() != host.thread()) {
            TimeUnit.NANOSECONDS.sleep(nanos);
            return;
        }
        host.checkStop();
        if (Thread.interrupted()) {
            throw new InterruptedException("sleep interrupted");
        }
        apiCalls++;
        now += StrictMath.max(nanos, apiCostNanos);
        if (now >= limit) {
            yieldTurn();
        }
    }

    @Override
    public long nanoTime() {
        if (Thread.currentThread() != host.thread()) {
            return System.nanoTime();
        }
        enter();
        long t = now;
        leave();
        return t;
    }

    @Override
    public long currentTimeMillis() {
        if (Thread.currentThread() != host.thread()) {
            return System.currentTimeMillis();
        }
        enter();
        long t = EPOCH_MILLIS + now / 1_000_000L;
        leave();
        return t;
    }

    @Override
    public void pause() {
        if (Thread.currentThread() != host.thread()) {
            Thread.onSpinWait();
            return;
        }
        enter();
        leave();
    }

    @Override
    public void checkpoint() {
        // The controller's thread unwinds when asked to stop; so does every thread it started.
        host.checkStop();
    }

    @Override
    public boolean onControllerThread() {
        return Thread.currentThread() == host.thread();
    }

    @Override
    public void brokeRule(String what) {
        host.brokeRule(what);
    }

    @Override
    public void adopt(Thread thread) {
        host.adopt(thread);
    }

    /** The controller has ended: it never needs to run again. */
    void ended() {
        wake = Long.MAX_VALUE;
    }
}
