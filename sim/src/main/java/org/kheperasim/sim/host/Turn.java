package org.kheperasim.sim.host;

import java.util.concurrent.locks.LockSupport;

/**
 * The turn: exactly one thread of a run, its holder, runs at any moment: the run's owner or one
 * controller thread. The holder passes the turn by naming the next holder's {@link Seat}; a thread
 * waiting for the turn parks until it is handed the turn. Where the run keeps its threads on one
 * core ({@link #keepOn}), each waiting thread moves there at its first wait and never spins;
 * elsewhere it spins for a short while first, when there are spare cores and its turn typically
 * comes back soon. This class is the whole hand-off protocol; who gets the turn next is the
 * engine's decision (see {@link Lockstep}).
 */
final class Turn {
    /**
     * How long a thread waiting for its turn spins before it parks, while there are spare cores:
     * long enough to ride out a short preemption of the holder, since waking a parked thread can
     * cost a millisecond on a virtual machine.
     */
    private static final long SPIN_NANOS = Long.getLong("kheperasim.spinMicros", 5_000) * 1000;
    /** A thread spins only when its turn typically comes back within this much real time. */
    private static final long SPIN_WORTH_NANOS = Long.getLong("kheperasim.spinWorthMicros", 100) * 1000;
    /** Threads may spin while they leave a core for the holder: cores − 1 at most. */
    private static final int MAX_SPINNERS = Runtime.getRuntime().availableProcessors() - 1;
    /** Threads spinning now, across every run in this JVM. */
    private static final java.util.concurrent.atomic.AtomicInteger SPINNERS =
            new java.util.concurrent.atomic.AtomicInteger();

    /** One thread that takes turns, and whether it is parked waiting for one. */
    static final class Seat {
        private volatile Thread thread;
        private volatile boolean parked;
        /**
         * How long this seat's thread typically waits for its turn, real ns (a moving average):
         * spinning pays only when the turn comes back soon, as between a lone controller and the
         * engine; with many controllers, or a busy machine, the wait is long and the thread parks at
         * once instead of burning a core the holder could use.
         */
        long typicalWaitNanos;
        /** The monitor whose real {@code wait} the seat's thread waits in for its turn, or null. */
        volatile Object waitMonitor;
        /** A virtual thread parks at once: parking and waking one costs less than a spin. */
        private volatile boolean virtual;
        /** The core the seat's thread has kept itself on (see {@link CpuAffinity}), or -1; its own thread's. */
        private int pinnedTo = -1;
        /** The core it last tried to keep to, or -1: a failed try is not repeated at every wait. */
        private int pinTried = -1;
        /** Its thread's id in the operating system, once pinned (to let it free again), else -1. */
        private volatile long tid = -1;
        /**
         * Where the seat's thread is: {@link #STUDENT} (the controller's own code), {@link #SIMULATOR}
         * (the simulator's: an API call, a hand-off, the world's step, its end), or {@link #TAKEN}: the
         * watchdog took the turn from it in the controller's code, and it must never enter the
         * simulator's again. The watchdog takes the turn only from a thread in the controller's code,
         * so a thread that the wall clock calls hung never touches the run while another steps it.
         * Written through {@link #WHERE}: the entry and the watchdog's take are atomic exchanges out
         * of {@link #STUDENT}, so only one of them wins; the way out is a plain release store, since
         * nobody else writes while it is {@link #SIMULATOR} (an atomic exchange there cost a sixth
         * of a lone robot's speed, two of them at every API call: bench).
         */
        private volatile int where = STUDENT;

        /** {@link #where}'s handle, for its atomic exchanges. */
        static final java.lang.invoke.VarHandle WHERE;

        static {
            try {
                WHERE = java.lang.invoke.MethodHandles.lookup().findVarHandle(Seat.class, "where", int.class);
            } catch (ReflectiveOperationException e) {
                throw new ExceptionInInitializerError(e);
            }
        }

        Seat(Thread thread) {
            this.thread = thread;
        }

        /**
         * The seat's thread enters the simulator's code (nested entries stay inside).
         *
         * @return the state to restore on the way out ({@link #leaveSimulator}), or {@link #TAKEN} when the
         *         turn was taken from it: it must not touch the run
         */
        int enterSimulator() {
            int w = where;
            if (w != STUDENT) {
                return w; // inside already, or taken: only the watchdog writes, and only out of STUDENT
            }
            // Atomic against the watchdog's take (takeFromStuck): it fails only when the take came first.
            return WHERE.compareAndSet(this, STUDENT, SIMULATOR) ? STUDENT : where;
        }

        /** @param before what {@link #enterSimulator} returned: back to the controller's code when it was there */
        void leaveSimulator(int before) {
            // Only when inside (never over a take: a call that found itself taken leaves too). Nobody
            // else writes while it is SIMULATOR, so the look and the store cannot be split; the release
            // orders the simulator's writes before a later take, whose exchange reads it.
            if (before == STUDENT && where == SIMULATOR) {
                WHERE.setRelease(this, STUDENT);
            }
        }

        /** @return true while the seat's thread runs the simulator's code */
        boolean inSimulator() {
            return where == SIMULATOR;
        }

        /** @return true when the turn was taken from it ({@link Turn#takeFromStuck}) */
        boolean taken() {
            return where == TAKEN;
        }

        Thread thread() {
            return thread;
        }

        /** The seat's thread, when it is created after the seat (a controller thread). */
        void seat(Thread t) {
            thread = t;
        }

        /** The seat's thread, when it is created after the seat; {@code virtual} when it is a virtual thread. */
        void seat(Thread t, boolean virtual) {
            this.virtual = virtual;
            thread = t;
        }
    }

    /** {@link Seat}'s thread runs the controller's code. */
    static final int STUDENT = 0;
    /** {@link Seat}'s thread runs the simulator's code. */
    static final int SIMULATOR = 1;
    /** The turn was taken from {@link Seat}'s thread in the controller's code. */
    static final int TAKEN = -1;

    private volatile Seat holder;
    /** The core the threads that wait for the turn keep to, or -1 (see {@link #keepOn}). */
    private volatile int cpu = -1;

    /** @param first the seat that holds the turn at the start */
    Turn(Seat first) {
        this.holder = first;
    }

    /**
     * From now on every platform thread that waits for this turn keeps itself on {@code core}, so a
     * hand-over is a switch on one core, not a wake-up of another (see {@link CpuAffinity}); and
     * none of them spins, which would only take that core from the holder.
     *
     * @param core a core from {@link CpuAffinity#claim}, or -1: threads stay where the system puts them
     */
    void keepOn(int core) {
        cpu = core;
    }

    /** @return the core the waiting threads keep to, or -1 */
    int core() {
        return cpu;
    }

    /** The calling thread, {@code me}'s, waits for this turn: first it moves to the turn's core, once. */
    void settle(Seat me) {
        int c = cpu;
        if (c >= 0 && me.pinTried != c && !me.virtual) {
            // Tried once per core: where the call fails the thread stays free (and may spin), as without pinning.
            me.pinTried = c;
            if (CpuAffinity.pinCallingThread(c)) {
                me.pinnedTo = c;
                me.tid = CpuAffinity.callingThreadId();
            } else {
                me.pinnedTo = -1;
            }
        }
    }

    /** Let {@code seat}'s thread run on every core again (a hung controller's, taken off the run but still running). */
    static void free(Seat seat) {
        CpuAffinity.unpin(seat.tid);
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
        Object monitor = next.waitMonitor;
        if (monitor != null) {
            // It waits inside the monitor's wait (which frees the monitor meanwhile): wake it there.
            synchronized (monitor) {
                monitor.notifyAll();
            }
        } else if (next.parked) {
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

    /**
     * Take the turn from {@code from}, a thread that made no progress for the hang timeout, if it
     * still holds it and runs the controller's code: from then on that thread never enters the
     * simulator's code (see {@link Seat#enterSimulator}). A thread inside the simulator's code (an API
     * call, a hand-off, the world's step) is never taken from: it touches the world, the robots and the
     * command log, and under load it may merely be waiting for a core.
     *
     * @return true when the turn was taken
     */
    synchronized boolean takeFromStuck(Seat from, Seat to) {
        if (holder != from || !Seat.WHERE.compareAndSet(from, STUDENT, TAKEN)) {
            return false;
        }
        giveTo(to);
        return true;
    }

    /**
     * Wait until {@code me} holds the turn: spin for a short while if a core is free (no more
     * threads spin than there are cores besides the holder's, so waiting threads never starve the
     * one that runs), then park.
     */
    void await(Seat me) {
        if (holder == me) {
            return;
        }
        settle(me);
        long start = System.nanoTime();
        if (!me.virtual && me.pinnedTo < 0 && me.typicalWaitNanos < SPIN_WORTH_NANOS && reserveSpin()) {
            try {
                int spins = 0;
                while (holder != me && spinning(++spins, start)) {
                    // spin
                }
            } finally {
                SPINNERS.decrementAndGet();
            }
        }
        boolean interrupted = false;
        while (holder != me) {
            me.parked = true;
            if (holder != me) {
                LockSupport.park(this);
            }
            me.parked = false;
            // An interrupt ends park at once: keep it for the thread's code, and park again.
            interrupted |= Thread.interrupted();
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        me.typicalWaitNanos += (System.nanoTime() - start - me.typicalWaitNanos) / 8;
    }

    /** @return true when this thread may spin (a core is free for it); it must then release the slot */
    private static boolean reserveSpin() {
        while (true) {
            int n = SPINNERS.get();
            if (n >= MAX_SPINNERS) {
                return false;
            }
            if (SPINNERS.compareAndSet(n, n + 1)) {
                return true;
            }
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
