package org.kheperasim.sim.host;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.LockSupport;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.RobotDriver;

/**
 * Runs an engine and its controllers in lockstep: exactly one thread, the <em>holder of the
 * turn</em>, runs at any moment, either a controller's code or the world (the holder calls
 * {@link Engine#advance()}, whoever it is). The thread that calls {@link #run} is the owner: it
 * holds the turn at the start and the end, and watches while the controllers have it.
 *
 * <p>The owner is the watchdog. While a controller holds the turn, the owner checks every
 * millisecond that the world or the controller makes progress; a controller whose thread has ended
 * (its {@code run()} returned) or that has made no API call and let no tick pass for the hang
 * timeout is taken off the run, and the owner carries on with the world. The simulation never hangs
 * on a controller.
 */
public final class Lockstep {
    /**
     * How long a controller waiting for its turn spins before it parks, while there are spare
     * cores: long enough to ride out a short preemption of the holder, since waking a parked thread
     * can cost a millisecond on a virtual machine.
     */
    private static final long SPIN_NANOS = Runtime.getRuntime().availableProcessors() > 1
            ? Long.getLong("kheperasim.spinMicros", 5_000) * 1000 : 0;
    private static final long WATCH_PERIOD_NANOS = 1_000_000L;

    private final Engine engine;
    private final List<ControllerHost> hosts;
    private final long hangTimeoutNanos;
    private Thread owner;
    private volatile Thread holder;
    private volatile boolean ownerWaiting;
    private volatile RuntimeException engineFailure;

    /**
     * @param engine the engine whose drivers are the hosts
     * @param hosts the controller hosts attached to it
     * @param hangTimeoutNanos real time without progress after which a controller is hung
     */
    public Lockstep(Engine engine, List<ControllerHost> hosts, long hangTimeoutNanos) {
        this.engine = engine;
        this.hosts = new ArrayList<>(hosts);
        this.hangTimeoutNanos = hangTimeoutNanos;
        for (ControllerHost h : hosts) {
            h.join(this);
        }
    }

    Engine engine() {
        return engine;
    }

    /**
     * Run until simulated time reaches {@code endNanos} or every controller has ended. Call it
     * from one thread, the owner; it returns holding the turn.
     *
     * @param endNanos simulated time to stop at, ns
     */
    public void run(long endNanos) {
        owner = Thread.currentThread();
        holder = owner;
        engine.setEnd(endNanos);
        while (true) {
            RobotDriver next = engine.advance();
            if (next == null) {
                return;
            }
            passTo(next);
            awaitOwner(Long.MAX_VALUE);
            RuntimeException failure = engineFailure;
            if (failure != null) {
                throw failure;
            }
        }
    }

    /** Stop every controller (at the end of a run); returns when they have unwound or been left behind. */
    public void stopAll() {
        for (ControllerHost h : hosts) {
            h.stop();
        }
    }

    /** @return true when {@code thread} holds the turn */
    boolean holds(Thread thread) {
        return holder == thread;
    }

    /**
     * Pass the turn: to a driver (a controller host), or with null back to the owner.
     *
     * @param next the driver the engine chose, or null
     */
    void passTo(RobotDriver next) {
        if (next == null) {
            holder = owner;
            if (ownerWaiting) {
                LockSupport.unpark(owner);
            }
            return;
        }
        ControllerHost host = (ControllerHost) next;
        holder = host.thread();
        host.receiveTurn();
    }

    /** The world threw while a controller's thread was stepping it: the owner rethrows it. */
    void engineFailed(Throwable e) {
        engineFailure = e instanceof RuntimeException r ? r
                : new IllegalStateException("the simulation failed: " + e, e);
    }

    /**
     * The owner waits for the turn to come back, watching the holder. Returns when the owner
     * holds the turn again, or when {@code maxNanos} of real time have passed.
     */
    void awaitOwner(long maxNanos) {
        long start = System.nanoTime();
        Thread watched = null;
        long progress = -1;
        long progressAt = start;
        while (holder != owner) {
            ownerWaiting = true;
            if (holder != owner) {
                LockSupport.parkNanos(this, WATCH_PERIOD_NANOS);
            }
            ownerWaiting = false;
            long now = System.nanoTime();
            Thread h = holder;
            if (h == owner) {
                return;
            }
            if (now - start > maxNanos) {
                return;
            }
            ControllerHost host = hostOf(h);
            if (host == null) {
                continue;
            }
            // TERMINATED, not !isAlive(): a thread just handed its first turn may not have started yet.
            if (h.getState() == Thread.State.TERMINATED) {
                if (holder == h) {
                    // Its run() returned while it held the turn: take the turn back.
                    holder = owner;
                    host.returned();
                }
                return;
            }
            long p = engine.ticks() + host.apiCalls();
            if (h != watched || p != progress) {
                watched = h;
                progress = p;
                progressAt = now;
            } else if (now - progressAt > hangTimeoutNanos && holder == h) {
                holder = owner;
                host.hung((now - progressAt) / 1e9);
                return;
            }
        }
    }

    private ControllerHost hostOf(Thread t) {
        for (ControllerHost h : hosts) {
            if (h.thread() == t) {
                return h;
            }
        }
        return null;
    }

    /** Spin once more, or (checking the clock every 256 spins) give up and park? */
    static boolean spinning(int spins, long since) {
        if ((spins & 255) != 0 || System.nanoTime() - since < SPIN_NANOS) {
            Thread.onSpinWait();
            return true;
        }
        return false;
    }
}
