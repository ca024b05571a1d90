package org.kheperasim.sim.run;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * Runs a {@link RunSession} on its own thread (the engine's thread), in chunks of simulated time,
 * paced against the wall clock by a speed factor (×0.25 … ×4, or as fast as possible). Pacing only
 * decides <em>when</em> the next chunk starts; chunk boundaries are tick boundaries, so a paced
 * run computes exactly what a headless run computes, and an arena edit is applied between two
 * chunks and stamped with the simulated time it took effect at.
 *
 * <p>Commands (start, pause, step, edit, stop) may come from any thread, the window's included;
 * they are queued and carried out by the session's thread between chunks, so nobody ever waits on
 * the engine and the engine never waits on the screen. After every chunk the latest snapshot is
 * published through {@link #latest()}.
 */
public final class PacedRunner implements AutoCloseable {

    /** Where the run is. */
    public enum State {
        /** Built, not started. */
        READY,
        /** Running chunks. */
        RUNNING,
        /** Paused (single steps allowed). */
        PAUSED,
        /** Every controller has ended. */
        FINISHED,
        /**
         * The run reached the end set by {@link #endAt} (the arena's time limit): the controllers were
         * stopped and the trace finished there, as at the end of a headless run of that length.
         */
        TIME_UP,
        /** Stopped by the user, or failed. */
        STOPPED
    }

    /**
     * Told on the session's thread after a snapshot is published: after every chunk, and once more
     * whenever the run stops running (paused, stepped, ended). Keep it short; it may read the
     * session's engine, which stands still while it is called.
     */
    @FunctionalInterface
    public interface PublishListener {
        /**
         * @param session the run
         * @param settled true when the run will not go on by itself (paused, ended): what it shows now stays
         */
        void published(RunSession session, boolean settled);
    }

    /** The speed factor meaning "as fast as possible". */
    public static final double MAX_SPEED = Double.POSITIVE_INFINITY;
    /** Simulated time a single step covers, ns. */
    public static final long STEP_NANOS = 10 * Engine.TICK_NANOS;
    /** Real time a paced chunk aims to cover, ns: short enough for smooth motion, long enough to be cheap. */
    private static final long CHUNK_WALL_NANOS = 4_000_000L;
    /**
     * At full speed a chunk is sized to last about this long in real time, from the speed of the
     * last chunk: edits and pauses still take effect within a blink, and the hand-off between the
     * controller's thread and this one (expensive on a small machine) is rare.
     */
    private static final long FULL_SPEED_CHUNK_WALL_NANOS = 20_000_000L;
    /** Bounds of a full-speed chunk, simulated ns. */
    private static final long MIN_FULL_CHUNK_NANOS = 100 * Engine.TICK_NANOS;
    private static final long MAX_FULL_CHUNK_NANOS = 10_000 * Engine.TICK_NANOS;
    /** Simulated ns per wall ns of the last full-speed chunk. */
    private double chunkRate;
    /** A run that falls this far behind its schedule stops trying to catch up. */
    private static final long MAX_LAG_NANOS = 250_000_000L;

    private final RunSession session;
    private final BlockingQueue<Runnable> commands = new LinkedBlockingQueue<>();
    private final AtomicReference<Snapshot> latest = new AtomicReference<>();
    private final Thread thread;
    private final CountDownLatch done = new CountDownLatch(1);
    private final List<Consumer<State>> stateListeners = new ArrayList<>();
    private final List<PublishListener> publishListeners = new java.util.concurrent.CopyOnWriteArrayList<>();
    private volatile State state = State.READY;
    private volatile double speed = 1;
    private volatile double realTimeFactor;
    private volatile Throwable failure;
    private volatile long endNanos = Long.MAX_VALUE;
    /** Where the run ends for good ({@link #endAt}), simulated ns. */
    private long limitNanos = Long.MAX_VALUE;
    private boolean stopRequested;
    private long anchorWall;
    private long anchorSim;
    private long rateWall;
    private long rateSim;

    /**
     * @param session the run (listeners and trace already added); this runner owns it from now on
     * @param stateListener told of every state change, on the session's thread (may be null)
     */
    public PacedRunner(RunSession session, Consumer<State> stateListener) {
        this.session = session;
        if (stateListener != null) {
            stateListeners.add(stateListener);
        }
        latest.set(session.snapshot());
        thread = new Thread(this::loop, "khepera-session");
        thread.setDaemon(true);
        thread.start();
    }

    /** @param factor simulated seconds per real second; {@link #MAX_SPEED} (or 0) for as fast as possible */
    public void setSpeed(double factor) {
        commands.add(() -> {
            speed = factor <= 0 ? MAX_SPEED : factor;
            anchor();
        });
    }

    /** @return the speed factor asked for */
    public double speed() {
        return speed;
    }

    /** @param endNanos simulated time at which the run pauses by itself (for benchmarks and tests) */
    public void pauseAt(long endNanos) {
        commands.add(() -> this.endNanos = endNanos);
    }

    /**
     * End the run at this simulated time, as a headless run of that length ends: the controllers are
     * stopped there, the trace finished, and the state becomes {@link State#TIME_UP}. The window
     * sets the arena's time limit, so its run and {@code run}'s end and score at the same moment.
     *
     * @param endNanos simulated time, ns
     */
    public void endAt(long endNanos) {
        commands.add(() -> limitNanos = endNanos);
    }

    /** @param l told after every published snapshot, on the session's thread */
    public void addPublishListener(PublishListener l) {
        publishListeners.add(l);
    }

    /** Start, or resume after a pause. */
    public void start() {
        commands.add(() -> {
            if (state == State.READY || state == State.PAUSED) {
                anchor();
                setState(State.RUNNING);
            }
        });
    }

    /** Pause: no more chunks until {@link #start()} or {@link #step()}. */
    public void pause() {
        commands.add(() -> {
            if (state == State.RUNNING || state == State.READY) {
                setState(State.PAUSED);
            }
        });
    }

    /** Run one step of {@link #STEP_NANOS} simulated time, then pause. */
    public void step() {
        commands.add(() -> {
            if (state == State.READY || state == State.PAUSED || state == State.RUNNING) {
                setState(State.PAUSED);
                chunk(StrictMath.min(session.timeNanos() + STEP_NANOS, limitNanos));
            }
        });
    }

    /**
     * Apply an arena edit at the next chunk boundary; it is stamped with the simulated time then.
     *
     * @param edited the edited arena (same size as the running one)
     */
    public void edit(Arena edited) {
        commands.add(() -> {
            if (state != State.STOPPED) {
                session.edit(edited);
                latest.set(session.snapshot());
            }
        });
    }

    /** Stop the run: the controllers are stopped and the session closed. */
    public void stop() {
        stopAsked = true;
        commands.add(() -> stopRequested = true);
    }

    /**
     * Set by {@link #stop} at once: the chunk being run ends at its next tick (a looping controller is asked to stop).
     */
    private volatile boolean stopAsked;

    /**
     * Stop and wait for the session's thread to finish.
     *
     * @param timeoutMillis how long to wait, real ms
     * @return true if it finished in time
     */
    public boolean stopAndWait(long timeoutMillis) {
        stop();
        try {
            return done.await(timeoutMillis, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    @Override
    public void close() {
        stopAndWait(5000);
    }

    /**
     * Run {@code task} on the session's thread between chunks and wait for it (for tests and
     * tools that need a consistent view).
     *
     * @param task what to run
     */
    public void runBetweenChunks(Runnable task) {
        CountDownLatch ran = new CountDownLatch(1);
        commands.add(() -> {
            try {
                task.run();
            } finally {
                ran.countDown();
            }
        });
        try {
            ran.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** @return the latest snapshot, published after every chunk (never null) */
    public Snapshot latest() {
        return latest.get();
    }

    /** @return where the run is */
    public State state() {
        return state;
    }

    /** @return simulated seconds per real second over the last half second or so of running */
    public double realTimeFactor() {
        return realTimeFactor;
    }

    /** @return what ended the run with an error, or null */
    public Throwable failure() {
        return failure;
    }

    /** @return the session (read its edits or result once the run has stopped) */
    public RunSession session() {
        return session;
    }

    private void loop() {
        try {
            while (!stopRequested && session.timeNanos() < limitNanos) {
                Runnable c = state == State.RUNNING ? commands.poll() : commands.poll(50, TimeUnit.MILLISECONDS);
                if (c != null) {
                    c.run();
                    continue;
                }
                if (state != State.RUNNING) {
                    continue;
                }
                long chunk = speed == MAX_SPEED ? fullSpeedChunk()
                        : StrictMath.max(Engine.TICK_NANOS,
                                (long) (CHUNK_WALL_NANOS * speed) / Engine.TICK_NANOS * Engine.TICK_NANOS);
                long target = StrictMath.min(StrictMath.min(session.timeNanos() + chunk, limitNanos),
                        StrictMath.max(endNanos, session.timeNanos()));
                if (target <= session.timeNanos()) {
                    setState(State.PAUSED);
                    continue;
                }
                chunk(target);
                if (session.timeNanos() >= limitNanos) {
                    break;
                }
                pace();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (Throwable e) {
            failure = e;
        } finally {
            try {
                session.close();
            } catch (RuntimeException e) {
                if (failure == null) {
                    failure = e;
                }
            }
            latest.set(session.snapshot());
            if (state != State.FINISHED && !stopRequested && failure == null && session.timeNanos() >= limitNanos) {
                setState(State.TIME_UP);
            } else if (state != State.FINISHED) {
                setState(State.STOPPED);
            } else {
                published(true);
            }
            done.countDown();
        }
    }

    private long fullSpeedChunk() {
        long ticks = (long) (chunkRate * FULL_SPEED_CHUNK_WALL_NANOS) / Engine.TICK_NANOS;
        return StrictMath.max(MIN_FULL_CHUNK_NANOS, StrictMath.min(MAX_FULL_CHUNK_NANOS, ticks * Engine.TICK_NANOS));
    }

    private void chunk(long target) {
        long wall = System.nanoTime();
        long sim = session.timeNanos();
        boolean more = session.runTo(target, () -> stopAsked);
        long took = System.nanoTime() - wall;
        if (took > 0) {
            chunkRate = (session.timeNanos() - sim) / (double) took;
        }
        latest.set(session.snapshot());
        if (!more && !stopAsked) {
            // Ended by itself; after a Stop (which may have ended a looping controller) it is stopped.
            setState(State.FINISHED);
        } else {
            published(state != State.RUNNING);
        }
    }

    private void published(boolean settled) {
        for (PublishListener l : publishListeners) {
            l.published(session, settled);
        }
    }

    private void anchor() {
        anchorWall = System.nanoTime();
        anchorSim = session.timeNanos();
        rateWall = anchorWall;
        rateSim = anchorSim;
    }

    /** Sleep until the wall clock catches up with simulated time (waking early for a command). */
    private void pace() throws InterruptedException {
        long now = System.nanoTime();
        if (now - rateWall >= 500_000_000L) {
            realTimeFactor = (session.timeNanos() - rateSim) / (double) (now - rateWall);
            rateWall = now;
            rateSim = session.timeNanos();
        }
        if (speed == MAX_SPEED || state != State.RUNNING) {
            return;
        }
        long due = anchorWall + (long) ((session.timeNanos() - anchorSim) / speed);
        long wait = due - now;
        if (wait < -MAX_LAG_NANOS) {
            anchorWall = now;
            anchorSim = session.timeNanos();
        } else {
            while (wait > 0) {
                Runnable c = commands.poll(wait, TimeUnit.NANOSECONDS);
                if (c == null) {
                    return;
                }
                c.run();
                if (stopRequested || state != State.RUNNING) {
                    return;
                }
                due = anchorWall + (long) ((session.timeNanos() - anchorSim) / speed);
                wait = due - System.nanoTime();
            }
        }
    }

    private void setState(State s) {
        state = s;
        if (s != State.RUNNING) {
            published(true);
        }
        for (Consumer<State> l : stateListeners) {
            l.accept(s);
        }
    }
}
