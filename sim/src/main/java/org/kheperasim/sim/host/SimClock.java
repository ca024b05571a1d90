package org.kheperasim.sim.host;

import java.time.Duration;
import java.util.concurrent.TimeUnit;

/**
 * The static hooks that controller bytecode calls instead of {@code Thread.sleep},
 * {@code System.currentTimeMillis}, {@code System.nanoTime}, {@code Thread.yield} and
 * {@code Thread.onSpinWait}: the controller class loader rewrites those calls to land here, so that
 * unmodified student code lives on the simulation clock.
 *
 * <p>Each hook asks the {@link Clock} bound to the calling thread. A thread with no clock bound
 * (a thread the controller started itself, or any code outside the simulator) gets the real
 * behaviour, so rewritten code never breaks, it only stops being deterministic.
 */
public final class SimClock {

    /** The simulated time of one controller thread. */
    public interface Clock {
        /** Block the controller for this much simulated time. @param nanos ≥ 0 */
        void sleepNanos(long nanos) throws InterruptedException;

        /** @return simulated nanoseconds since the run started (charges one API call) */
        long nanoTime();

        /** @return simulated epoch milliseconds (charges one API call) */
        long currentTimeMillis();

        /** A yield or spin-wait hint: charges one API call so that spin loops make time pass. */
        void pause();

        /** Called at loop back-edges of controller code: throws when the controller must stop. */
        void checkpoint();

        /** @return true on the controller's own thread (not a thread it started) */
        boolean onControllerThread();

        /**
         * The controller broke a rule of the simulator (it called {@code System.exit}, waited with
         * nothing to wake it, ...): the run records the fault and stops the controller.
         *
         * @param what the call, for the user
         */
        void brokeRule(String what);

        /**
         * A thread the controller starts: it belongs to the run and ends with it.
         *
         * @return true when the run starts it itself, in the lockstep (the caller must not start it)
         */
        boolean adopt(Thread thread);
    }

    // Inheritable: the host binds the clock on the engine thread while it constructs the controller
    // Thread object, and the controller thread inherits it when it starts.
    private static final ThreadLocal<Clock> CURRENT = new InheritableThreadLocal<>();

    /**
     * Count of clocks with a stop pending; while it is zero the back-edge checkpoint costs one
     * volatile read and nothing else.
     */
    private static volatile int stopsPending;

    private SimClock() {
    }

    /** @return the clock of the calling thread's run, or null outside a run */
    static Clock current() {
        return CURRENT.get();
    }

    /** Bind {@code clock} to the calling thread (the controller thread, at its start). */
    public static void bind(Clock clock) {
        CURRENT.set(clock);
    }

    /**
     * Unbind the calling thread's clock. The thread keeps an empty entry rather than none: a step
     * controller binds and unbinds at every step, and looking up a thread-local that has no entry
     * makes one each time (at a cost a swarm notices).
     */
    public static void unbind() {
        CURRENT.set(null);
    }

    /** A host that wants a controller stopped announces it, so checkpoints start looking. */
    static synchronized void stopRequested() {
        stopsPending++;
    }

    /** The stop has been delivered or the controller has ended. */
    static synchronized void stopSettled() {
        if (stopsPending > 0) {
            stopsPending--;
        }
    }

    /** Replaces {@link Thread#sleep(long)}. @param millis simulated milliseconds */
    public static void sleep(long millis) throws InterruptedException {
        if (millis < 0) {
            throw new IllegalArgumentException("timeout value is negative");
        }
        Clock c = CURRENT.get();
        if (c == null) {
            Thread.sleep(millis);
        } else {
            c.sleepNanos(TimeUnit.MILLISECONDS.toNanos(millis));
        }
    }

    /** Replaces {@link Thread#sleep(long, int)}. */
    public static void sleep(long millis, int nanos) throws InterruptedException {
        if (millis < 0) {
            throw new IllegalArgumentException("timeout value is negative");
        }
        if (nanos < 0 || nanos > 999_999) {
            throw new IllegalArgumentException("nanosecond timeout value out of range");
        }
        Clock c = CURRENT.get();
        if (c == null) {
            Thread.sleep(millis, nanos);
        } else {
            c.sleepNanos(TimeUnit.MILLISECONDS.toNanos(millis) + nanos);
        }
    }

    /** Replaces {@link TimeUnit#sleep(long)} (an instance call; the unit becomes the first argument). */
    public static void sleep(TimeUnit unit, long duration) throws InterruptedException {
        Clock c = CURRENT.get();
        if (c == null) {
            unit.sleep(duration);
        } else if (duration > 0) {
            c.sleepNanos(unit.toNanos(duration));
        }
    }

    /** Replaces {@code Thread.sleep(Duration)} (Java 19+). */
    public static void sleep(Duration duration) throws InterruptedException {
        long nanos;
        try {
            nanos = duration.toNanos();
        } catch (ArithmeticException e) {
            nanos = Long.MAX_VALUE;
        }
        Clock c = CURRENT.get();
        if (c == null) {
            if (nanos > 0) {
                TimeUnit.NANOSECONDS.sleep(nanos);
            }
        } else if (nanos > 0) {
            c.sleepNanos(nanos);
        }
    }

    /** Replaces {@link System#currentTimeMillis()}. */
    public static long currentTimeMillis() {
        Clock c = CURRENT.get();
        return c == null ? System.currentTimeMillis() : c.currentTimeMillis();
    }

    /** Replaces {@link System#nanoTime()}. */
    public static long nanoTime() {
        Clock c = CURRENT.get();
        return c == null ? System.nanoTime() : c.nanoTime();
    }

    /** Replaces {@link Thread#yield()}. */
    public static void yield() {
        Clock c = CURRENT.get();
        if (c == null) {
            Thread.yield();
        } else {
            c.pause();
        }
    }

    /** Replaces {@link Thread#onSpinWait()}. */
    public static void onSpinWait() {
        Clock c = CURRENT.get();
        if (c == null) {
            Thread.onSpinWait();
        } else {
            c.pause();
        }
    }

    /**
     * Threads whose construction of a controller overran (see {@link ConstructionWatch}): their next checkpoint throws.
     */
    private static final java.util.Set<Thread> STOP_CONSTRUCTING = java.util.concurrent.ConcurrentHashMap.newKeySet();

    /** The construction of a controller on {@code thread} overran: stop it at its next checkpoint. */
    static void stopConstructing(Thread thread) {
        STOP_CONSTRUCTING.add(thread);
        stopRequested();
    }

    /** The construction on {@code thread} that {@link #stopConstructing} stopped has ended. */
    static void constructed(Thread thread) {
        if (STOP_CONSTRUCTING.remove(thread)) {
            stopSettled();
        }
    }

    /** Inserted at every loop back-edge of controller code: lets a runaway loop be stopped. */
    public static void checkpoint() {
        if (stopsPending != 0) {
            if (!STOP_CONSTRUCTING.isEmpty() && STOP_CONSTRUCTING.contains(Thread.currentThread())) {
                throw new ControllerStoppedError("the controller's construction ran too long");
            }
            Clock c = CURRENT.get();
            if (c != null) {
                c.checkpoint();
            }
        }
    }
}
