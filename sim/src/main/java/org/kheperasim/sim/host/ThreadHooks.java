package org.kheperasim.sim.host;

/**
 * What the controller class loader puts in place of the thread calls of contained controller code,
 * so that the threads a controller starts take part in the lockstep on the simulated clock:
 * {@code Thread.start}, {@code join}, {@code isAlive}, {@code interrupt}, {@code isInterrupted},
 * {@code getState}, {@code getStackTrace} and {@code Thread.currentThread} (which answer for the
 * {@code Thread} object even when a virtual thread runs its code, see {@link ThreadRunners});
 * {@code synchronized}
 * blocks and methods; {@code Object.wait}, {@code notify} and {@code notifyAll}. Each has the
 * signature of what it replaces (an instance method's receiver comes first).
 *
 * <p>On a thread of the controller that holds the turn they act on the controller's
 * {@link ControllerThreads}; on any other thread (the Swing event thread of a controller's own
 * window, code outside a run) they do what the original does.
 */
public final class ThreadHooks {
    private ThreadHooks() {
    }

    /** @return the clock of the run when the calling thread is the controller's thread holding the turn, else null */
    private static ControllerClock onTurn() {
        return SimClock.current() instanceof ControllerClock c && c.onTurn() ? c : null;
    }

    /** Replaces {@link Thread#start()}: a thread a controller starts belongs to its run. */
    public static void start(Thread thread) {
        SimClock.Clock c = SimClock.current();
        if (c != null && c.adopt(thread)) {
            return;
        }
        thread.start();
    }

    /** Replaces {@link Thread#join()}. */
    public static void join(Thread thread) throws InterruptedException {
        join(thread, 0);
    }

    /** Replaces {@link Thread#join(long)}: on the simulated clock when the thread is one of the controller's. */
    public static void join(Thread thread, long millis) throws InterruptedException {
        ControllerClock c = onTurn();
        Participant p = c == null ? null : c.participant(thread);
        if (p == null) {
            ThreadRunners.of(thread).join(millis);
            return;
        }
        if (millis < 0) {
            throw new IllegalArgumentException("timeout value is negative");
        }
        if (Thread.interrupted()) {
            throw new InterruptedException("join interrupted");
        }
        c.join(p, millis);
    }

    /** Replaces {@link Thread#join(long, int)}. */
    public static void join(Thread thread, long millis, int nanos) throws InterruptedException {
        join(thread, millis + (nanos > 0 && millis < Long.MAX_VALUE ? 1 : 0));
    }

    /** Replaces {@link Thread#isAlive()}: a thread of the controller is alive from its start() until it ends. */
    public static boolean isAlive(Thread thread) {
        ControllerClock c = onTurn();
        Participant p = c == null ? null : c.participant(thread);
        return p == null ? ThreadRunners.of(thread).isAlive() : !p.done;
    }

    /**
     * Replaces {@code super.start()} in a {@code Thread} subclass's own {@code start()}: the thread
     * joins the run as with {@link #start}; outside a run its code runs on a thread of its own
     * ({@code Thread.start} itself cannot be reached past the override).
     */
    public static void superStart(Thread thread) {
        SimClock.Clock c = SimClock.current();
        if (c != null && c.adopt(thread)) {
            return;
        }
        if (ThreadRunners.started(thread)) {
            throw new IllegalThreadStateException("thread '" + thread.getName() + "' was already started");
        }
        ThreadRunners.strayRunner(thread, true,
                (t, e) -> thread.getUncaughtExceptionHandler().uncaughtException(thread, e))
                .start();
    }

    /**
     * Replaces {@link Thread#interrupt()}: a thread of the controller that sleeps or waits wakes at
     * once. A class's own {@code interrupt()} is called as Java would, and interrupts only when it
     * calls {@code super.interrupt()} ({@link #superInterrupt}).
     */
    public static void interrupt(Thread thread) {
        thread.interrupt();
        if (!ThreadRunners.overridesInterrupt(thread.getClass())) {
            superInterrupt(thread);
        }
    }

    /**
     * Replaces {@code super.interrupt()} in a {@code Thread} subclass's own {@code interrupt()},
     * and does what {@link #interrupt} asks of {@code Thread}: the thread running the object's code
     * is interrupted, and the lockstep told.
     */
    public static void superInterrupt(Thread thread) {
        Thread runner = ThreadRunners.of(thread);
        if (runner != thread) {
            runner.interrupt();
        }
        ControllerClock c = onTurn();
        Participant p = c == null ? null : c.participant(thread);
        if (p != null) {
            p.interruptPending = true;
            c.interrupt(p);
        } else if (SimClock.current() instanceof ControllerClock mine && !ThreadRunners.started(thread)) {
            // Not started yet: it starts interrupted, whichever thread then runs its code.
            mine.interruptedUnstarted(thread);
        }
    }

    /**
     * Replaces {@link Thread#isInterrupted()}: for a thread of the controller, the flag of the thread running its code.
     */
    public static boolean isInterrupted(Thread thread) {
        ControllerClock c = onTurn();
        Participant p = c == null ? null : c.participant(thread);
        return p == null ? ThreadRunners.of(thread).isInterrupted() : c.interrupted(p);
    }

    /**
     * Replaces {@link Thread#getState()}: for a thread of the controller, its state in the lockstep
     * (the same however the real threads were scheduled); for any other, the state of the thread
     * that runs its code.
     */
    public static Thread.State getState(Thread thread) {
        ControllerClock c = onTurn();
        Participant p = c == null ? null : c.participant(thread);
        return p == null ? ThreadRunners.of(thread).getState() : c.state(p);
    }

    /**
     * Replaces {@link Thread#getStackTrace()}: the stack of the thread that runs its code, as a
     * platform thread running it would show it (without this hook's frame, or the frames below the
     * code that a virtual thread runs it from).
     */
    public static StackTraceElement[] getStackTrace(Thread thread) {
        Thread runner = ThreadRunners.of(thread);
        StackTraceElement[] trace = runner.getStackTrace();
        java.util.List<StackTraceElement> kept = new java.util.ArrayList<>(trace.length);
        for (StackTraceElement e : trace) {
            if (e.getClassName().startsWith(ThreadRunners.class.getName())) {
                break;
            }
            if (!e.getClassName().equals(ThreadHooks.class.getName())) {
                kept.add(e);
            }
        }
        return kept.toArray(new StackTraceElement[0]);
    }

    /** Replaces {@link Thread#currentThread()}: on a thread of the controller, its {@code Thread} object. */
    public static Thread currentThread() {
        ControllerClock c = onTurn();
        return c == null ? ThreadRunners.objectOf(Thread.currentThread()) : c.runningThread();
    }

    /** Put before every {@code monitorenter} of controller code (and at the start of a synchronized method). */
    public static void monitorEnter(Object monitor) {
        ControllerClock c = onTurn();
        if (c != null && monitor != null) {
            c.monitorEnter(monitor);
        }
    }

    /** Put before every {@code monitorexit} of controller code (and at each exit of a synchronized method). */
    public static void monitorExit(Object monitor) {
        ControllerClock c = onTurn();
        if (c != null && monitor != null) {
            c.monitorExit(monitor);
        }
    }

    /** Replaces {@link Object#wait(long)}: simulated time passes, and the controller's other threads run. */
    public static void waitFor(Object monitor, long millis) throws InterruptedException {
        ControllerClock c = onTurn();
        if (c == null) {
            monitor.wait(millis);
            return;
        }
        if (millis < 0) {
            throw new IllegalArgumentException("timeout value is negative");
        }
        if (!Thread.holdsLock(monitor)) {
            throw new IllegalMonitorStateException("current thread is not owner");
        }
        if (millis == 0 && !c.othersAlive()) {
            Containment.refuse("called Object.wait() with no timeout, and no other thread of the controller could"
                    + " notify it (use Thread.sleep)");
        }
        c.waitOn(monitor, millis);
    }

    /** Replaces {@link Object#wait(long, int)}. */
    public static void waitFor(Object monitor, long millis, int nanos) throws InterruptedException {
        waitFor(monitor, millis + (nanos > 0 && millis < Long.MAX_VALUE ? 1 : 0));
    }

    /** Replaces {@link Object#wait()}: only another thread of the controller can notify it. */
    public static void waitForever(Object monitor) throws InterruptedException {
        waitFor(monitor, 0);
    }

    /** Replaces {@link Object#notify()}. */
    public static void notify(Object monitor) {
        monitor.notify();
        ControllerClock c = onTurn();
        if (c != null) {
            c.notifyWaiters(monitor, false);
        }
    }

    /** Replaces {@link Object#notifyAll()}. */
    public static void notifyAll(Object monitor) {
        monitor.notifyAll();
        ControllerClock c = onTurn();
        if (c != null) {
            c.notifyWaiters(monitor, true);
        }
    }
}
