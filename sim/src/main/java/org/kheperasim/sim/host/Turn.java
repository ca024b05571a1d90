package org.kheperasim.sim.host;

import java.util.concurrent.locks.LockSupport;

/**
 * The turn: exactly one thread of a run, its holder, runs at any moment: the run's owner or one
 * controller thread. The holder passes the turn by naming the next holder's {@link Seat}; a thread
 * waiting for the turn spins for a short while (only where there are spare cores), then parks until
 * it is handed the turn. This class is the whole hand-off protocol; who gets the turn next is the
 * engine's decision (see {@link Lockstep}).
 */
final class Turn {
    /**
     * How long a thread waiting for its turn spins before it parks, while there are spare cores:
     * long enough to ride out a short preemption of the holder, since waking a parked thread can
     * cost a millisecond on a virtual machine.
     */
    private static final long SPIN_NANOS = Runtime.getRuntime().availableProcessors() > 1
            ? Long.getLong("kheperasim.spinMicros", 5_000) * 1000 : 0;

    /** One thread that takes turns, and whether it is parked waiting for one. */
    static final class Seat {
        private volatile Thread thread;
        private volatile boolean parked;

        Seat(Thread thread) {
            this.thread = thread;
        }

        Thread thread() {
            return thread;
        }

        /** The seat's thread, when it is created after the seat (a controller thread). */
        void seat(Thread t) {
            thread = t;
        }
    }

    private volatile Seat holder;

    /** @param first the seat that holds the turn at the start */
    Turn(Seat first) {
        this.holder = first;
    }

    /** @return true when {@code seat} holds the turn */
    boolean heldBy(Seat seat) {
        return holder == seat;
    }

    /** @return the seat holding the turn */
    Seat holder() {
        return holder;
    }

    /** Give the turn to {@code next}, waking it if it parked waiting for it. */
    void giveTo(Seat next) {
        holder = next;
        if (next.parked) {
            LockSupport.unpark(next.thread);
        }
    }

    /**
     * Take the turn from {@code from} if it still holds it (the watchdog taking the turn back from
     * a controller that ended or hung).
     *
     * @return true when the turn was taken
     */
    synchronized boolean takeFrom(Seat from, Seat to) {
        if (holder != from) {
            return false;
        }
        giveTo(to);
        return true;
    }

    /** Wait until {@code me} holds the turn: spin while there are spare cores, then park. */
    void await(Seat me) {
        long spinStart = 0;
        int spins = 0;
        while (holder != me) {
            if (spins == 0) {
                spinStart = System.nanoTime();
            }
            if (spinning(++spins, spinStart)) {
                continue;
            }
            me.parked = true;
            if (holder != me) {
                LockSupport.park(this);
            }
            me.parked = false;
        }
    }

    /**
     * Wait until {@code me} holds the turn or about {@code maxNanos} of real time have passed (the
     * owner, which watches while it waits).
     */
    void awaitFor(Seat me, long maxNanos) {
        if (holder == me) {
            return;
        }
        me.parked = true;
        if (holder != me) {
            LockSupport.parkNanos(this, maxNanos);
        }
        me.parked = false;
    }

    /** Spin once more, or (checking the clock every 256 spins) give up and park? */
    private static boolean spinning(int spins, long since) {
        if ((spins & 255) != 0 || System.nanoTime() - since < SPIN_NANOS) {
            Thread.onSpinWait();
            return true;
        }
        return false;
    }
}
