package org.kheperasim.sim.serve;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import org.kheperasim.link.protocol.dialect.Dialect;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.engine.view.SnapshotListener;

/**
 * An arena whose robots answer the robot's serial protocol, each to its own client: one engine,
 * run in real time by its own thread, with a {@link ServedRobot} per robot. The robots meet each
 * other as in any run, so several Khepera clients can drive robots that meet in one arena.
 *
 * <p>Time: a client is a real program with a real clock, so the simulation tracks the wall clock:
 * every {@link ServedRobot#TICK_PERIOD_NANOS} the engine thread runs the engine up to
 * {@code (wall time since start) × speed}. Commands are applied between ticks under one lock, so a
 * command sees the world at one instant.
 */
public final class ServedArena implements AutoCloseable {
    private final Arena arena;
    private final Settings settings;
    private final Engine engine;
    private final double speed;
    private final ReentrantLock lock = new ReentrantLock();
    private final List<SimRobot> simRobots = new ArrayList<>();
    private List<ServedRobot> robots;
    private Thread ticker;
    private volatile boolean running;
    private volatile long wallStart;
    private volatile long leadNanos;
    private volatile long lastCommandNanos;
    /** The dialect {@code serve --dialect} gave for every robot, or null: each robot's own. */
    private volatile Dialect dialect;

    /**
     * @param arena the arena; each of its robot poses is a robot to serve
     * @param settings sensor, motor and link settings ({@code link.baud} sets the reply pacing)
     * @param seed the seed of the robots' noise
     * @param speed simulated seconds per wall-clock second, 1 for real time (0.1..100)
     */
    public ServedArena(Arena arena, Settings settings, long seed, double speed) {
        this(arena, settings, seed, speed, arena.robots().size());
    }

    /** Serve the first {@code count} robots of the arena only. */
    ServedArena(Arena arena, Settings settings, long seed, double speed, int count) {
        if (!(speed >= 0.1 && speed <= 100)) {
            throw new IllegalArgumentException("speed " + speed + " must lie in 0.1..100 (1 = real time)");
        }
        if (arena.robots().isEmpty()) {
            throw new IllegalArgumentException("arena " + arena.name()
                    + " has no robot start pose; add a 'robot' line");
        }
        this.arena = arena;
        this.settings = settings;
        this.speed = speed;
        this.engine = new Engine(new World(arena), seed);
        for (int i = 0; i < count; i++) {
            SimRobot robot = engine.addRobot(count == 1 ? "served" : "served#" + i, arena.robots().get(i), settings,
                    arena.robotType(i));
            robot.onBoard().servedDirectly();
            simRobots.add(robot);
        }
    }

    /**
     * Serve every robot in this dialect ({@code serve --dialect}) instead of its own.
     *
     * @param served the dialect, or null for each robot's own (its robot file's {@code dialect})
     * @return this arena
     */
    public ServedArena dialect(Dialect served) {
        this.dialect = served;
        return this;
    }

    /**
     * The one place that decides which protocol a served robot answers in: its type's dialect (an
     * e-puck answers as an e-puck), unless {@code serve --dialect} chose one for every robot.
     *
     * @param robot a robot of this arena
     * @return the dialect it answers in
     */
    Dialect dialectFor(SimRobot robot) {
        Dialect chosen = dialect;
        return chosen != null ? chosen : Dialect.named(robot.type().dialect());
    }

    /** @return the robots served, in the arena's order, each to be given to its own protocol server */
    public synchronized List<ServedRobot> robots() {
        if (robots == null) {
            List<ServedRobot> made = new ArrayList<>();
            for (SimRobot r : simRobots) {
                made.add(new ServedRobot(this, r));
            }
            robots = List.copyOf(made);
        }
        return robots;
    }

    /** @return the simulated robot {@code i} */
    SimRobot simRobot(int i) {
        return simRobots.get(i);
    }

    /**
     * Add a snapshot listener (a window, a recorder). Call before {@link #start()}; it is called on
     * the engine thread, holding the lock: keep it short.
     */
    public void addListener(SnapshotListener listener, long periodNanos) {
        lock.lock();
        try {
            engine.addListener(listener, periodNanos);
        } finally {
            lock.unlock();
        }
    }

    /** Start the engine thread, if it has not started: simulated time starts now. */
    public synchronized void start() {
        if (ticker != null) {
            return;
        }
        running = true;
        wallStart = System.nanoTime();
        ticker = new Thread(this::tickLoop, "served-arena-engine");
        ticker.setDaemon(true);
        ticker.start();
    }

    /** See {@link ServedRobot#followClient(long)}. */
    void followClient(long leadNanos) {
        if (leadNanos < 0) {
            throw new IllegalArgumentException("lead " + leadNanos + " ns must not be negative (0 = off)");
        }
        this.leadNanos = leadNanos;
    }

    private void tickLoop() {
        while (running) {
            long now = System.nanoTime();
            long target = (long) ((now - wallStart) * speed);
            long lead = leadNanos;
            if (lead > 0 && target > lastCommandNanos + lead) {
                // The client is late: hold the robots' time, and resume the pacing from here.
                target = lastCommandNanos + lead;
                wallStart = now - (long) (target / speed);
            }
            target -= target % Engine.TICK_NANOS;
            lock.lock();
            try {
                if (target > engine.timeNanos()) {
                    engine.runUntil(target);
                }
            } finally {
                lock.unlock();
            }
            LockSupport.parkNanos(ServedRobot.TICK_PERIOD_NANOS);
        }
    }

    ReentrantLock lock() {
        return lock;
    }

    /** A command arrived now (held under the lock). */
    void commandSeen() {
        lastCommandNanos = engine.timeNanos();
    }

    /** @return simulated time, ns (the caller holds the lock) */
    long timeHeld() {
        return engine.timeNanos();
    }

    /** @return the world now (taken under the lock, between ticks) */
    public Snapshot snapshot() {
        lock.lock();
        try {
            return engine.snapshot();
        } finally {
            lock.unlock();
        }
    }

    /** @return simulated time now, ns */
    public long timeNanos() {
        lock.lock();
        try {
            return engine.timeNanos();
        } finally {
            lock.unlock();
        }
    }

    /** @return simulated seconds per wall-clock second */
    public double speed() {
        return speed;
    }

    /** @return the arena served */
    public Arena arena() {
        return arena;
    }

    /** @return the settings the robots were built with */
    public Settings settings() {
        return settings;
    }

    /** @return the run's seed */
    public long seed() {
        return engine.seed();
    }

    /** Stop the engine thread. */
    @Override
    public synchronized void close() {
        running = false;
        if (ticker != null) {
            ticker.interrupt();
            try {
                ticker.join(TimeUnit.SECONDS.toMillis(5));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
