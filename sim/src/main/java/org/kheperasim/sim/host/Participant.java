package org.kheperasim.sim.host;

/**
 * One thread of a controller in the lockstep: the controller's own thread, or a thread its code
 * started. Each waits for the {@link Turn} on its own {@link Turn.Seat}; the controller's
 * {@link ControllerThreads} decides which of them runs next. Only the thread holding the turn
 * touches these fields (the turn's hand-over is a volatile write and read).
 */
final class Participant {
    /** Position in the controller's threads: 0 is the controller's own; ties are broken by it. */
    final int index;
    final Thread thread;
    /**
     * The thread that runs its code: {@link #thread} itself, or once started, a virtual thread
     * calling its {@code run()} (see {@link ThreadRunners}). Read by the watchdog.
     */
    volatile Thread runner;
    final Turn.Seat seat;
    /** Simulated time it next wants to run at, ns; {@link Long#MAX_VALUE} while it waits with no timeout. */
    long wake;
    boolean started;
    boolean done;
    /** A monitor it must own before it can go on (it is blocked on it, or was woken from a wait on it); or null. */
    Object lock;
    /** True while it waits in {@code Object.wait} for a notify (or its timeout). */
    boolean waiting;
    /** The order of its wait among every wait of the controller: notify wakes the longest waiting. */
    long waitOrder;
    /** How many times it had entered {@link #lock} when it began to wait: it re-enters as often. */
    int lockCount;
    /**
     * Its interrupt flag as the others see it while it is not running: its own flag when it last
     * gave up the turn, set by an interrupt since. Its real flag cannot tell them: a thread waiting
     * for its turn clears it to park again (and sets it back when its turn comes), at a moment
     * only the wall clock decides.
     */
    volatile boolean interruptPending;
    /**
     * What its {@code getState()} says while it waits for the turn: RUNNABLE when its slice ran out,
     * TIMED_WAITING in a sleep, WAITING or TIMED_WAITING in a wait or join (blocked on a monitor is
     * told by {@link #lock}).
     */
    Thread.State waitingAs = Thread.State.RUNNABLE;
    /** While it is in {@code join}: WAITING, or TIMED_WAITING with a timeout; else null. */
    Thread.State joining;

    Participant(int index, Thread thread, long wake) {
        this.index = index;
        this.thread = thread;
        this.runner = thread;
        this.seat = new Turn.Seat(thread);
        this.wake = wake;
    }

    /**
     * Choose the thread that will run its code (see {@link ThreadRunners}), and make it ready: on
     * the thread that constructed the controller, just after, for the threads that exist then; on
     * the thread that starts it for the others.
     *
     * @param clock the controller's clock, bound in the runner
     * @param contained true when the controller's code is contained (see {@link ThreadRunners#runnerOf})
     * @param handler told what its code threw
     */
    void chooseRunner(SimClock.Clock clock, boolean contained, Thread.UncaughtExceptionHandler handler) {
        Thread r = ThreadRunners.runnerOf(thread, clock, contained, index == 0, handler);
        if (r != thread) {
            runner = r;
            seat.seat(r, !(r instanceof ThreadRunners.Runner));
        }
    }

    /**
     * Start its thread, the first time it is given the turn. An interrupt its code received before
     * its start is carried to a runner: told by the lockstep's record for an object whose methods
     * are the student's, by its own flag otherwise.
     */
    void start() {
        Thread r = runner;
        if (r != thread && (interruptPending
                || !ThreadRunners.overrides(thread.getClass()) && thread.isInterrupted())) {
            r.interrupt();
        }
        started = true;
        r.start();
    }

    /** Is {@code t} this participant's thread, or the thread running its code? */
    boolean is(Thread t) {
        return thread == t || runner == t;
    }

    /**
     * Interrupt it: the thread running its code, and the object its code knows when its
     * {@code interrupt()} is the JDK's (an override is never called: nothing reads the object's own
     * flag when another thread runs its code).
     */
    void interrupt() {
        Thread r = runner;
        if (r == thread || !ThreadRunners.overrides(thread.getClass())) {
            thread.interrupt();
        }
        if (r != thread) {
            r.interrupt();
        }
    }

    @Override
    public String toString() {
        return index == 0 ? "the controller's own" : "'" + thread.getName() + "'";
    }
}
