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
     * Choose the thread that will run the controller's own code (see {@link ThreadRunners}); on the
     * thread that constructed the controller, just after. The threads its code starts keep
     * theirs: they may ask for a stack size, which a virtual thread cannot honour.
     *
     * @param clock the controller's clock, bound in the runner
     * @param contained true when the controller's code is contained (see {@link ThreadRunners#runnerOf})
     */
    void chooseRunner(SimClock.Clock clock, boolean contained) {
        Thread r = ThreadRunners.runnerOf(thread, clock, contained);
        if (r != thread) {
            runner = r;
            seat.seat(r, true);
        }
    }

    /** Start its thread, the first time it is given the turn. */
    void start() {
        Thread r = runner;
        if (r != thread && thread.isInterrupted()) {
            r.interrupt();
        }
        started = true;
        r.start();
    }

    /** Is {@code t} this participant's thread, or the thread running its code? */
    boolean is(Thread t) {
        return thread == t || runner == t;
    }

    /** Interrupt it: the object its code knows, and the thread running that code. */
    void interrupt() {
        thread.interrupt();
        Thread r = runner;
        if (r != thread) {
            r.interrupt();
        }
    }

    @Override
    public String toString() {
        return index == 0 ? "the controller's own" : "'" + thread.getName() + "'";
    }
}
