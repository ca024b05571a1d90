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

    Participant(int index, Thread thread, long wake) {
        this.index = index;
        this.thread = thread;
        this.seat = new Turn.Seat(thread);
        this.wake = wake;
    }

    @Override
    public String toString() {
        return index == 0 ? "the controller's own" : "'" + thread.getName() + "'";
    }
}
