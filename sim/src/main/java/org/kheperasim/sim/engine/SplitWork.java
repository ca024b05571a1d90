package org.kheperasim.sim.engine;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.function.IntConsumer;

/**
 * Work on every robot that no robot's result depends on the order of (each robot's scan at a
 * stop, each lone robot's glide), split between the thread that holds the turn and one helper
 * thread of the engine's own, so that a large swarm uses two cores. The two take chunks of robots
 * in turn; both end before {@link #forEach} returns, so to everything else
 * the engine still runs on one thread at a time. What each robot computes depends only on itself
 * and on what no part writes (the world, the other robots' poses), so a run gives the same trace
 * with one thread or two, byte for byte ({@code SwarmThreadsTest}).
 *
 * <p>The helper waits for work spinning for a short while (a stop of a 1,000-robot swarm comes
 * every few hundred microseconds of wall time), then parked; it ends with {@link #close}.
 */
final class SplitWork implements AutoCloseable {
    /** Below this many robots a split costs more than it gains. */
    static final int MIN_ROBOTS = 64;
    /** Robots per chunk the two threads take in turn. */
    private static final int CHUNK = 16;
    /** How long the helper spins for the next piece of work before it parks, ns. */
    private static final long SPIN_NANOS = 20_000;
    private static final long OPEN = 0;
    private static final long JOINED = 1;
    private static final long CLOSED = 2;

    private final Thread helper;
    /** The number of the last piece of work handed out; the helper takes a piece when it sees a new one. */
    private volatile long handed;
    /** The last piece the helper is done with. */
    private volatile long finished;
    /** {@code piece * 4 + OPEN}: the helper may join; {@code + JOINED}: it has; {@code + CLOSED}: too late. */
    private final AtomicLong state = new AtomicLong();
    /** The next index to take. */
    private final AtomicInteger next = new AtomicInteger();
    private volatile boolean closed;
    private volatile boolean parked;
    private IntConsumer body;
    private int count;
    private volatile Throwable failure;

    /** @param name the helper thread's name */
    SplitWork(String name) {
        helper = new Thread(null, this::loop, name, 0, false);
        helper.setDaemon(true);
        helper.start();
    }

    /**
     * Run {@code body} for every index {@code 0 .. count - 1}, in chunks taken in turn by this
     * thread and the helper: a helper that is slow to come (a busy machine) leaves this thread more
     * of the work, never a wait for its start. Each index must touch only what is its own.
     *
     * @param count how many indices
     * @param body the work of one index
     */
    void forEach(int count, IntConsumer body) {
        this.body = body;
        this.count = count;
        this.failure = null;
        next.set(0);
        long piece = handed + 1;
        state.set(piece * 4 + OPEN);
        handed = piece; // publishes body and count
        if (parked) {
            LockSupport.unpark(helper);
        }
        Throwable mine = null;
        try {
            work(body, count);
        } catch (RuntimeException | Error e) {
            mine = e;
            next.set(count); // the helper takes no more
        }
        if (!state.compareAndSet(piece * 4 + OPEN, piece * 4 + CLOSED)) {
            // The helper joined: wait for the chunk it holds.
            // Its chunk is short; if it is taking long, its thread is waiting for a core: give it ours.
            long spinUntil = System.nanoTime() + 20_000;
            while (finished != piece) {
                if (System.nanoTime() < spinUntil) {
                    Thread.onSpinWait();
                } else {
                    Thread.yield();
                }
            }
        }
        this.body = null;
        Throwable theirs = failure;
        if (mine != null) {
            rethrow(mine);
        }
        if (theirs != null) {
            rethrow(theirs);
        }
    }

    private void work(IntConsumer body, int count) {
        int i;
        while ((i = next.getAndAdd(CHUNK)) < count) {
            int end = StrictMath.min(count, i + CHUNK);
            for (int k = i; k < end; k++) {
                body.accept(k);
            }
        }
    }

    private static void rethrow(Throwable t) {
        if (t instanceof RuntimeException r) {
            throw r;
        }
        throw (Error) t;
    }

    private void loop() {
        long done = 0;
        while (true) {
            long spinUntil = System.nanoTime() + SPIN_NANOS;
            while (handed == done && !closed) {
                if (System.nanoTime() < spinUntil) {
                    Thread.onSpinWait();
                } else {
                    parked = true;
                    if (handed == done && !closed) {
                        LockSupport.park(this);
                    }
                    parked = false;
                }
            }
            if (closed) {
                return;
            }
            long piece = handed;
            if (state.compareAndSet(piece * 4 + OPEN, piece * 4 + JOINED)) {
                try {
                    work(body, count);
                } catch (RuntimeException | Error e) {
                    failure = e;
                    next.set(Integer.MAX_VALUE / 2);
                }
            }
            done = piece;
            finished = piece;
        }
    }

    /** Ends the helper thread. */
    @Override
    public void close() {
        closed = true;
        LockSupport.unpark(helper);
    }
}
