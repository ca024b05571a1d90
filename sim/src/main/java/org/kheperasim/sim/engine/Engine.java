package org.kheperasim.sim.engine;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.function.Function;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.model.Ticks;
import org.kheperasim.sim.engine.model.WsuProfile;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.DriverRecorder;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.engine.view.SnapshotListener;
import org.kheperasim.sim.engine.view.VisionView;

/**
 * The simulation engine: advances the world in fixed ticks of simulated time, runs each robot's
 * driver (its controller) in lockstep with that clock, and publishes snapshots to listeners. It
 * never reads the wall clock and never touches the screen, so the same inputs give the same run on
 * any machine, with or without a window.
 *
 * <p>One tick at time t: commands and poll-cycle events due by t take effect; every driver whose
 * wake time falls before t + tick runs up to t + tick, seeing the world as of t; listeners due at t
 * receive a snapshot; then every robot moves through the tick. See {@link #advance()}.
 */
public final class Engine {
    /** The tick: 1 ms of simulated time. */
    public static final long TICK_NANOS = Ticks.NANOS;


    private final World world;
    private final long seed;
    private final SplittableRandom seeds;
    private final List<SimRobot> robots = new ArrayList<>();
    private final List<RobotDriver> drivers = new ArrayList<>();
    private final List<Function<SimRobot, String>> driverStatus = new ArrayList<>();
    private final List<Subscription> listeners = new ArrayList<>();
    private final Motion motion;
    private long tick;
    private long endNanos = Long.MAX_VALUE;
    private boolean inTick;
    private int driverCursor;
    private boolean hasDrivers;
    /** A robot steps by ticks ({@code engine.stepping=tick}): the world stops at every tick, the reference. */
    private boolean ticking;
    /** Hears what the drivers do (a command log), or null. */
    private DriverRecorder recorder;
    /** The robot whose driver had the last turn, until its wake has been told to the recorder; -1: none. */
    private int granted = -1;
    private long grantedTick;
    private boolean wakesTold;
    /** Splits each stop's per-robot work over two threads (a large swarm), or null: the turn holder does it all. */
    private SplitWork split;
    /** Told the time each stretch of moves ended at, ns, after every robot moved (see {@link #watchMoves}), or null. */
    private java.util.function.LongConsumer stretchWatch;

    private record Subscription(SnapshotListener listener, long periodTicks) {
    }

    /**
     * @param world the world
     * @param seed the run's seed: every random stream of the run is split from it
     */
    public Engine(World world, long seed) {
        this.world = world;
        this.seed = seed;
        this.seeds = new SplittableRandom(seed);
        this.motion = new Motion(robots, world.bodies());
    }

    /**
     * Add a robot. Each robot gets its own random stream, split from the seed in the order robots
     * are added.
     *
     * @param name a name for reports
     * @param start start pose
     * @param settings its settings
     * @return the robot, a {@link RobotTypes#KHEPERA1}
     */
    public SimRobot addRobot(String name, Pose start, Settings settings) {
        return addRobot(name, start, settings, RobotTypes.KHEPERA1);
    }

    /**
     * Add a robot of a given type. Each robot gets its own random stream, split from the seed in
     * the order robots are added.
     *
     * @param name a name for reports
     * @param start start pose
     * @param settings its settings
     * @param type its type: body, wheels, sensors
     * @return the robot
     */
    public SimRobot addRobot(String name, Pose start, Settings settings, RobotType type) {
        RobotType t = WsuProfile.robotFor(settings, type);
        SimRobot r = new SimRobot(robots.size(), name, world, start, WsuProfile.settingsFor(settings, t),
                t, seeds.split());
        robots.add(r);
        if (recorder != null) {
            r.record(recorder);
        }
        ticking |= r.steppingByTicks();
        drivers.add(null);
        driverStatus.add(x -> "none");
        return r;
    }

    /**
     * @param robot a robot of this engine
     * @param driver what drives it
     * @param status tells the driver's state for snapshots
     */
    public void attach(SimRobot robot, RobotDriver driver, Function<SimRobot, String> status) {
        drivers.set(robot.id(), driver);
        hasDrivers = true;
        driverStatus.set(robot.id(), status);
    }

    /**
     * Let the world's step use two threads, for a swarm of {@link SplitWork#MIN_ROBOTS} robots or
     * more (call after adding the robots; fewer are not worth it): the run is the same with one
     * thread or two. {@link #close} ends the second thread.
     *
     * @param threads 1 or 2
     */
    public void threads(int threads) {
        if (threads > 1 && split == null && robots.size() >= SplitWork.MIN_ROBOTS) {
            split = new SplitWork("khepera-sim world step, second thread");
            motion.split(split);
        } else if (threads <= 1 && split != null) {
            close();
        }
    }

    /** Ends the engine's second thread, if it has one (the engine runs on with one). */
    public void close() {
        if (split != null) {
            split.close();
            split = null;
            motion.split(null);
        }
    }

    /**
     * @param listener receives snapshots
     * @param periodNanos how often, a whole number of ticks (a tick's length for every tick)
     */
    public void addListener(SnapshotListener listener, long periodNanos) {
        if (periodNanos < TICK_NANOS || periodNanos % TICK_NANOS != 0) {
            throw new IllegalArgumentException("listener period " + periodNanos
                    + " ns must be a whole number of 1 ms ticks");
        }
        listeners.add(new Subscription(listener, periodNanos / TICK_NANOS));
    }

    /**
     * Tell a recorder everything the drivers do from now on (set it before the controllers are made:
     * a constructor may already command its robot).
     *
     * @param recorder hears the commands, emergency stops and wake times, in the engine's order
     */
    public void record(DriverRecorder recorder) {
        this.recorder = recorder;
        for (SimRobot r : robots) {
            r.record(recorder);
        }
    }

    /**
     * Watch every move, without changing any: the engine's events ({@code engine.event.EngineEvents}).
     *
     * @param moved told each robot's every move's end, ns, on the thread moving it (robots added so far)
     * @param stretch told the end of each stretch, ns, by the turn holder, once every robot has moved
     */
    public void watchMoves(java.util.function.ObjLongConsumer<SimRobot> moved,
            java.util.function.LongConsumer stretch) {
        stretchWatch = stretch;
        for (SimRobot r : robots) {
            r.watchMoves(moved);
        }
    }

    /** @param listener a listener to stop calling */
    public void removeListener(SnapshotListener listener) {
        listeners.removeIf(s -> s.listener == listener);
    }

    /** @return ticks completed so far (a cheap progress counter for watchdogs) */
    public long ticks() {
        return tick;
    }

    /** @return simulated time now, ns */
    public long timeNanos() {
        return tick * TICK_NANOS;
    }

    /** @return the run's seed */
    public long seed() {
        return seed;
    }

    /** @return the world */
    public World world() {
        return world;
    }

    /** @return the robots, in order */
    public List<SimRobot> robots() {
        return List.copyOf(robots);
    }

    /** @return true while at least one driver has not ended */
    public boolean anyDriverRunning() {
        for (RobotDriver d : drivers) {
            if (d != null && d.wakeNanos() != Long.MAX_VALUE) {
                return true;
            }
        }
        return false;
    }

    /**
     * Set where {@link #advance()} stops: the run's end.
     *
     * @param endNanos simulated time, ns
     */
    public void setEnd(long endNanos) {
        this.endNanos = endNanos;
    }

    /**
     * End the run early, at {@code nanos} or where it is set to end if that comes first: a stop that
     * the wall clock decides (a signal, the window's Stop). The recorder hears it, so that a replay of
     * the run ends where the run did.
     *
     * @param nanos simulated time, ns
     */
    public void stopAt(long nanos) {
        if (nanos < endNanos) {
            endNanos = nanos;
            if (recorder != null) {
                recorder.stoppedAt(nanos);
            }
        }
    }

    /** @return where {@link #advance()} stops, ns (set by {@link #setEnd}) */
    public long endNanos() {
        return endNanos;
    }

    /**
     * Advance the world until a driver must run, or until the end set by {@link #setEnd} is
     * reached or every driver has ended. Whoever holds the turn calls this, the engine's owner or a
     * controller thread that has just used up its slice: the world does not care which thread
     * steps it, only that one thread at a time does.
     *
     * <p>The order within a tick at time t never changes: commands and poll events due by t; each
     * driver in robot order whose wake time falls before t + tick runs to t + tick (this method
     * returns it, after {@link RobotDriver#grant granting} it that slice; the next call carries on
     * with the next driver); listeners due at t; every robot moves through the tick.
     *
     * @return the driver that must run now, or null when the run is over
     */
    public RobotDriver advance() {
        if (recorder != null) {
            tellWakes();
        }
        while (true) {
            if (!inTick) {
                if (tick * TICK_NANOS >= endNanos || (hasDrivers && !anyDriverRunning())) {
                    return null;
                }
                long t = tick * TICK_NANOS;
                if (split != null) {
                    // Each robot's commands, scan and poll at the stop are its own; the world stands still meanwhile.
                    split.forEach(robots.size(), i -> robots.get(i).beginTick(t));
                } else {
                    for (int i = 0; i < robots.size(); i++) {
                        robots.get(i).beginTick(t);
                    }
                }
                inTick = true;
                driverCursor = 0;
            }
            long end = (tick + 1) * TICK_NANOS;
            while (driverCursor < drivers.size()) {
                RobotDriver d = drivers.get(driverCursor++);
                if (d != null && d.wakeNanos() < end) {
                    d.grant(end);
                    granted = driverCursor - 1;
                    grantedTick = tick;
                    return d;
                }
            }
            publish();
            // A program on the robot reads the scan of its next wake's window: that scan is taken at its tick.
            for (int i = 0; i < drivers.size(); i++) {
                RobotDriver d = drivers.get(i);
                if (d != null) {
                    robots.get(i).wantScan(d.wakeNanos());
                }
            }
            long n = quietTicks();
            motion.move(tick, n);
            if (stretchWatch != null) {
                stretchWatch.accept((tick + n) * TICK_NANOS);
            }
            tick += n;
            inTick = false;
        }
    }

    /** The recorder hears each driver's wake at the start, then the wake of the driver whose turn has just ended. */
    private void tellWakes() {
        if (!wakesTold) {
            wakesTold = true;
            for (int i = 0; i < drivers.size(); i++) {
                if (drivers.get(i) != null) {
                    recorder.wake(i, -1, drivers.get(i).wakeNanos());
                }
            }
        } else if (granted >= 0) {
            recorder.wake(granted, grantedTick, drivers.get(granted).wakeNanos());
        }
        granted = -1;
    }

    /**
     * How many ticks the world can move through at once: up to the next tick at which anything is
     * due (a command, a noise redraw, a position-move update, a controller's wake-up, a snapshot,
     * the end; for a lone robot, its own commands, redraws and updates do not count); at least one. Each robot then
     * moves through the stretch as cheaply as it can (see {@link Motion}).
     */
    private long quietTicks() {
        if (ticking || (hasDrivers && !anyDriverRunning())) {
            // The reference stepping stops at every tick; a run whose controllers have all ended ends with this tick.
            return 1;
        }
        long limit = Ticks.ceil(endNanos) - tick;
        for (int i = 0; i < drivers.size(); i++) {
            RobotDriver d = drivers.get(i);
            if (d != null) {
                long w = d.wakeNanos();
                if (w != Long.MAX_VALUE) {
                    limit = StrictMath.min(limit, w / TICK_NANOS - tick);
                }
            }
        }
        for (int k = 0; k < listeners.size(); k++) {
            long p = listeners.get(k).periodTicks;
            limit = StrictMath.min(limit, (tick / p + 1) * p - tick);
        }
        // A lone robot begins the ticks where its own commands and noise redraws fall due itself, inside
        // its move (Motion.alone): nothing else happens at those ticks, so the world need not stop there.
        for (int i = 0; i < robots.size() && limit > 1 && robots.size() > 1; i++) {
            long due = robots.get(i).nextDueNanos();
            if (due != Long.MAX_VALUE) {
                limit = StrictMath.min(limit, Ticks.ceil(due) - tick);
            }
        }
        return StrictMath.max(1, limit);
    }

    /**
     * Advance the world by one tick. Only for an engine without drivers (tests, tools); a run with
     * controllers goes through the controller host, which runs them in lockstep.
     */
    public void step() {
        runUntil(timeNanos() + TICK_NANOS);
    }

    /**
     * Run an engine without drivers until {@code endNanos}.
     *
     * @param endNanos simulated time to stop at, ns
     * @throws IllegalStateException if a driver needs to run: use the controller host
     */
    public void runUntil(long endNanos) {
        setEnd(endNanos);
        if (advance() != null) {
            throw new IllegalStateException("this engine has controllers: run it through the controller host");
        }
    }

    private void publish() {
        Snapshot snapshot = null;
        for (int k = 0; k < listeners.size(); k++) {
            Subscription s = listeners.get(k);
            if (tick % s.periodTicks == 0) {
                if (snapshot == null) {
                    snapshot = snapshot();
                }
                s.listener.onSnapshot(snapshot);
            }
        }
    }

    /**
     * Edit the arena during a run (an instructor drops a wall in front of a robot): walls, lights
     * and regions are replaced, and cap i of {@code edited} moves cap i unless a gripper holds it.
     * Robots keep their poses. Call it between ticks, from the thread that holds the turn (the
     * run's owner between {@code Lockstep.run} calls); a run that replays its edits at the same
     * ticks computes the same trace.
     *
     * @param edited the edited arena, of the same size
     * @throws IllegalArgumentException if the size differs
     * @throws IllegalStateException inside a tick
     */
    public void edit(org.kheperasim.sim.arena.Arena edited) {
        if (inTick) {
            throw new IllegalStateException(
                    "the arena can only be edited between ticks, by the thread holding the turn");
        }
        // Values of the scans left for a later read are those of the arena as it was.
        for (SimRobot r : robots) {
            r.settleScan();
        }
        world.replaceArena(edited);
        for (SimRobot r : robots) {
            r.arenaEdited();
        }
    }

    /** @return the world as it is now */
    public Snapshot snapshot() {
        List<RobotView> views = new ArrayList<>(robots.size());
        int first = robots.isEmpty() ? 0 : robots.get(0).type().sensorCount();
        int[] prox = new int[first];
        int[] light = new int[first];
        for (SimRobot r : robots) {
            if (prox.length != r.type().sensorCount()) {
                prox = new int[r.type().sensorCount()];
                light = new int[prox.length];
            }
            r.copyVisible(timeNanos(), prox, light);
            views.add(new RobotView(r.id(), r.name(), r.x(), r.y(), r.headingDeg(), r.speedLeft(), r.speedRight(),
                    r.encoderLeft(), r.encoderRight(), r.contact(), prox, light, r.collisions(),
                    r.distanceTravelledMm(), driverStatus.get(r.id()).apply(r), r.gripper().view(),
                    r.leds(), r.type()));
        }
        List<VisionView> vision = new ArrayList<>();
        for (SimRobot r : robots) {
            if (r.vision().lastView() != null) {
                vision.add(r.vision().lastView());
            }
        }
        return new Snapshot(timeNanos(), views, world.caps(), vision);
    }
}
