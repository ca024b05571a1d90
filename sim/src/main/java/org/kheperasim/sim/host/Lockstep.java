package org.kheperasim.sim.host;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.RobotDriver;

/**
 * Runs an engine and its controllers in lockstep: exactly one thread, the holder of the
 * {@link Turn}, runs at any moment, either a controller's code or the world (the holder calls
 * {@link Engine#advance()}, whoever it is). The thread that calls {@link #run} is the owner: it
 * holds the turn at the start and the end, and watches while the controllers have it.
 *
 * <p>The owner is the watchdog. While a controller holds the turn, the owner checks every
 * millisecond that the world or the controller makes progress; a controller whose thread has ended
 * (its {@code run()} returned) or that has made no API call and let no tick pass for the hang
 * timeout is taken off the run, and the owner carries on with the world. The simulation never hangs
 * on a controller.
 *
 * <p>What the wall clock decides here (a hang, a stop's patience, the heap's charge to the holder)
 * reaches the world only through the turn: a controller is taken off the run only while its thread
 * is in its own code, never inside the simulator's (see {@link Turn#takeFromStuck}), so its robot's
 * emergency stop and its last wake are told to the command log by whoever holds the turn, in the
 * engine's order, and the log's replay is the run.
 */
public final class Lockstep {
    private static final long WATCH_PERIOD_NANOS = 1_000_000L;
    /** The heap is looked at every this many watch periods. */
    private static final int HEAP_WATCH_EVERY = 100;

    private final Engine engine;
    private final List<ControllerHost> hosts;
    private final List<StepHost> steps;
    private final Map<RobotDriver, ControllerHost> byDriver = new IdentityHashMap<>();
    private final long hangTimeoutNanos;
    private final Turn.Seat owner = new Turn.Seat(null);
    private final Turn turn = new Turn(owner);
    private volatile RuntimeException engineFailure;
    /** Asked (by the owner, while it watches) whether the run should stop early; never null. */
    private java.util.function.BooleanSupplier stopAsked = () -> false;
    /** Set by the owner when {@link #stopAsked} said yes: whoever steps the world ends the run at the next tick. */
    private volatile boolean stopping;
    /** While the run is being stopped, how long a holder may make no progress before it is asked to stop, ns. */
    private static final long STOP_PATIENCE_NANOS = 200_000_000L;
    /** Set once the run has claimed a core for its controller threads (or found none to claim). */
    private boolean coreClaimed;

    /**
     * @param engine the engine whose drivers are the hosts
     * @param hosts the controller hosts attached to it
     * @param hangTimeoutNanos real time without progress after which a controller is hung
     */
    public Lockstep(Engine engine, List<ControllerHost> hosts, long hangTimeoutNanos) {
        this(engine, hosts, List.of(), hangTimeoutNanos);
    }

    /**
     * @param engine the engine whose drivers are the hosts
     * @param hosts the thread-style controller hosts attached to it
     * @param steps the step controllers attached to it, stepped inline by whoever holds the turn
     * @param hangTimeoutNanos real time without progress after which a controller is hung
     */
    public Lockstep(Engine engine, List<ControllerHost> hosts, List<StepHost> steps, long hangTimeoutNanos) {
        this.engine = engine;
        this.steps = List.copyOf(steps);
        this.hosts = new ArrayList<>(hosts);
        this.hangTimeoutNanos = hangTimeoutNanos;
        for (ControllerHost h : hosts) {
            byDriver.put(h, h);
            h.join(this);
        }
        if (pinning()) {
            CpuAffinity.prepare();
        }
    }

    /**
     * Start setting up the heap watch in the background: call it first when setting a run up, so
     * that the watch is ready, at no cost in waiting, when the controllers start.
     */
    public static void prepare() {
        HeapWatch.prepare();
    }

    Engine engine() {
        return engine;
    }

    Turn turn() {
        return turn;
    }

    /**
     * Run until simulated time reaches {@code endNanos} or every controller has ended. Call it
     * from one thread, the owner; it returns holding the turn.
     *
     * @param endNanos simulated time to stop at, ns
     */
    public void run(long endNanos) {
        run(endNanos, () -> false);
    }

    /**
     * Run until simulated time reaches {@code endNanos}, every controller has ended, or {@code stop}
     * says so. The owner asks {@code stop} each time it looks at the holder (about every millisecond
     * of real time) and before it steps the world itself; once it says yes, the run ends at the next
     * tick boundary, as if that were its end. Where exactly depends on the wall clock, like the
     * signal that asks for it; a run that is not stopped is computed the same with or without it.
     *
     * @param endNanos simulated time to stop at, ns
     * @param stop asked whether to stop early (e.g. on SIGTERM); cheap and thread-safe
     */
    public void run(long endNanos, java.util.function.BooleanSupplier stop) {
        if (!coreClaimed && pinning()) {
            // Kept for the whole run, window chunks included: given back when the controllers stop.
            coreClaimed = true;
            turn.keepOn(CpuAffinity.claim());
        }
        stopAsked = stop;
        stopping = stop.getAsBoolean();
        for (StepHost s : steps) {
            // The step watchdog asks it: a step that loops holds the thread that would.
            s.runStop(stop);
        }
        HeapWatch.awaitReady();
        owner.seat(Thread.currentThread());
        turn.giveTo(owner);
        engine.setEnd(endNanos);
        HeapWatch.listen(heapFull);
        try {
            while (true) {
                RobotDriver next = advance();
                if (next == null) {
                    return;
                }
                passTo(next);
                awaitOwner(Long.MAX_VALUE);
                RuntimeException failure = engineFailure;
                if (failure != null) {
                    throw failure;
                }
                for (ControllerHost h : hosts) {
                    if (h.threadsOutliveIt()) {
                        h.endThreads();
                    }
                }
            }
        } finally {
            HeapWatch.unlisten(heapFull);
        }
    }

    /**
     * The heap passed its threshold: the controller holding the turn is the one allocating, when its
     * thread is in its own code (inside the simulator's, the allocation may be the simulator's). The
     * charge stops it at its next API call, in its turn: its end is in the command log like any other.
     */
    private final java.util.function.Consumer<String> heapFull = what -> {
        Turn.Seat seat = turn.holder();
        ControllerHost holder = hostAt(seat);
        if (holder != null && !seat.inSimulator()) {
            holder.exceededMemory(what);
        }
    };

    /**
     * Advance the world until a thread-style controller must run: the step controllers that fall
     * due on the way are stepped here, inline, by whoever holds the turn.
     *
     * @return the controller to hand the turn to, or null when the run is over
     */
    private RobotDriver advance() {
        while (true) {
            // Asked here too, not only while the owner watches: with only step controllers (or a
            // thread that steps the world itself) nobody watches, and a signal must still end the run.
            if (!stopping && stopAsked.getAsBoolean()) {
                stopping = true;
            }
            if (stopping) {
                // Where is the wall clock's decision: the command log records it (Engine.stopAt).
                engine.stopAt(engine.timeNanos());
            }
            RobotDriver next = engine.advance();
            if (!(next instanceof StepHost step)) {
                return next;
            }
            step.step();
        }
    }

    /**
     * Step the world on the calling thread, which holds the turn for {@code host} and has nothing of
     * its own due in its slice, until some driver must run. The world is stepped only here and in
     * {@link #run}, whichever thread holds the turn: on a controller's thread when its slice ends,
     * which spares a hand-over to the owner and back at every tick.
     *
     * @param host the controller whose thread calls
     * @return true when the engine chose {@code host} again (it goes on, with a new slice); false when
     *         the turn has been passed to another driver, or back to the owner
     */
    boolean stepWorldFor(ControllerHost host) {
        RobotDriver next;
        try {
            next = advance();
        } catch (RuntimeException | Error e) {
            engineFailed(e);
            next = null;
        }
        if (next == host) {
            return true;
        }
        passTo(next);
        return false;
    }

    /** Stop every controller (at the end of a run); returns when they have unwound or been left behind. */
    public void stopAll() {
        try {
            for (ControllerHost h : hosts) {
                h.stop();
            }
            for (StepHost s : steps) {
                s.stop();
            }
        } finally {
            CpuAffinity.release(turn.core());
            turn.keepOn(-1);
        }
    }

    /**
     * Are the controllers' threads kept on one core (see {@link CpuAffinity})? Only where they hand
     * the turn to each other: two thread-style controllers or more, on platform threads.
     */
    private boolean pinning() {
        return hosts.size() >= 2 && !ThreadRunners.VIRTUAL;
    }

    /**
     * Pass the turn: to the controller the engine chose, or with null back to the owner.
     *
     * @param next the driver the engine chose, or null
     */
    void passTo(RobotDriver next) {
        if (next == null) {
            turn.giveTo(owner);
        } else {
            byDriver.get(next).receiveTurn(turn);
        }
    }

    /**
     * The owner takes the turn back from a thread that still holds it after its grace period.
     *
     * @return true when {@code seat} held the turn
     */
    boolean takeBack(Turn.Seat seat) {
        return turn.takeFrom(seat, owner);
    }

    /** The world threw while a controller's thread was stepping it: the owner rethrows it. */
    private void engineFailed(Throwable e) {
        engineFailure = e instanceof RuntimeException r ? r
                : new IllegalStateException("the simulation failed: " + e, e);
    }

    /**
     * The owner waits for the turn to come back, watching the holder. Returns when the owner
     * holds the turn again, or when {@code maxNanos} of real time have passed.
     */
    void awaitOwner(long maxNanos) {
        long start = System.nanoTime();
        ControllerHost watched = null;
        long progress = -1;
        long progressAt = start;
        int watches = 0;
        while (!turn.heldBy(owner)) {
            turn.awaitFor(owner, WATCH_PERIOD_NANOS);
            if (!stopping && stopAsked.getAsBoolean()) {
                stopping = true;
            }
            if (++watches % HEAP_WATCH_EVERY == 0) {
                String full = HeapWatch.nearlyFull();
                Turn.Seat seat = turn.holder();
                ControllerHost holder = hostAt(seat);
                if (full != null && holder != null && !seat.inSimulator()) {
                    holder.exceededMemory(full);
                }
            }
            long now = System.nanoTime();
            Turn.Seat seat = turn.holder();
            if (seat == owner || now - start > maxNanos) {
                return;
            }
            ControllerHost host = hostAt(seat);
            if (host == null) {
                continue;
            }
            Participant holder = host.participantAt(seat);
            if (exited(holder.runner)) {
                if (turn.takeFrom(seat, owner)) {
                    // Its run() returned while it held the turn.
                    if (holder.index == 0) {
                        host.returned();
                    } else {
                        host.helperReturned(holder);
                    }
                }
                return;
            }
            long p = engine.ticks() + host.apiCalls();
            if (host != watched || p != progress || seat.inSimulator()) {
                // The simulator's own code (an API call, a hand-off, the world's step) always ends: on a busy
                // machine its thread may wait long for a core, and is never called hung for that.
                watched = host;
                progress = p;
                progressAt = now;
            } else if (now - progressAt > hangTimeoutNanos && turn.takeFromStuck(seat, owner)) {
                host.hung(holder, (now - progressAt) / 1e9);
                // Still running somewhere in a library call, perhaps for ever: not on the others' core.
                Turn.free(seat);
                return;
            } else if (stopping && now - progressAt > STOP_PATIENCE_NANOS) {
                // The run is being stopped (a signal, the window's Stop): a controller that makes no progress
                // is asked to stop at its next loop rather than waited for until it counts as hung.
                host.stopSoon();
            }
        }
    }

    /**
     * Has this thread's {@code run()} returned (or thrown past its handler) while it held the turn?
     * TERMINATED, not {@code !isAlive()}: a thread just handed its first turn may not have started
     * yet. Or BLOCKED with no frame left: a platform thread that ends takes its own {@code Thread}
     * object's monitor to tell its joiners, and waits there while another thread of the controller
     * holds that monitor (a {@code synchronized} method of the controller) and sleeps, waiting for
     * the turn this thread will not give back.
     */
    private static boolean exited(Thread t) {
        Thread.State state = t.getState();
        return state == Thread.State.TERMINATED || state == Thread.State.BLOCKED && t.getStackTrace().length == 0;
    }

    private ControllerHost hostAt(Turn.Seat seat) {
        for (ControllerHost h : hosts) {
            if (h.participantAt(seat) != null) {
                return h;
            }
        }
        return null;
    }
}
