package org.kheperasim.sim.serve;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import org.kheperasim.api.GripperState;
import org.kheperasim.api.IrSensor;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.KheperaProtocol;
import org.kheperasim.link.protocol.TurretCommand;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.Settings;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.Snapshot;
import org.kheperasim.sim.engine.SnapshotListener;
import org.kheperasim.sim.engine.World;

/**
 * One simulated Khepera that answers the robot's serial protocol: an engine with one robot and no
 * controller (the client is the controller), run in real time by its own thread.
 *
 * <p>Time: a client is a real program with a real clock, so the simulation tracks the wall clock:
 * every {@link #TICK_PERIOD_NANOS} the engine thread runs the engine up to
 * {@code (wall time since start) × speed}. Commands are applied between ticks under one lock, so a
 * command sees the world at one instant. {@code speed} 1 is the real robot's pace; a larger factor
 * runs simulated time faster than the wall clock (the protocol server divides its reply pacing by the
 * same factor).
 *
 * <p>What each command does is in {@link #execute(Command)} and docs/protocol-server.md.
 */
public final class ServedRobot implements AutoCloseable {
    /** How often the engine thread catches up with the wall clock. */
    public static final long TICK_PERIOD_NANOS = TimeUnit.MILLISECONDS.toNanos(2);
    /** The BIOS and protocol versions {@code B} reports (the reference's example robot). */
    public static final String BIOS_VERSION = "5.02";
    /** See {@link #BIOS_VERSION}. */
    public static final String PROTOCOL_VERSION = "5.01";
    /** The gripper turret's version and revision, {@code T,1,B}. */
    public static final int[] GRIPPER_VERSION = {2, 1};
    /** What the optical barrier ({@code T,1,G}) reads with something between the fingers. */
    public static final int BARRIER_BROKEN = 255;
    /** What {@code T,1,H,0} reads with the fingers closed (0 when open). */
    public static final int FINGERS_CLOSED_POSITION = 255;

    private final Arena arena;
    private final Settings settings;
    private final Engine engine;
    private final SimRobot robot;
    private final double speed;
    private final LinkTiming timing;
    private final ReentrantLock lock = new ReentrantLock();
    private final int[] bus = new int[256];
    private final int[] speedPid = {3800, 800, 100};
    private final int[] positionPid = {3000, 20, 4000};
    private final int[] values = new int[IrSensor.COUNT];
    private Thread ticker;
    private volatile boolean running;
    private volatile long wallStart;
    private volatile long leadNanos;
    private volatile long lastCommandNanos;

    /**
     * @param arena the arena; its first robot pose is where the robot starts
     * @param settings sensor, motor and link settings ({@code link.baud} sets the reply pacing)
     * @param seed the seed of the robot's noise
     * @param speed simulated seconds per wall-clock second, 1 for real time (0.1..100)
     */
    public ServedRobot(Arena arena, Settings settings, long seed, double speed) {
        if (!(speed >= 0.1 && speed <= 100)) {
            throw new IllegalArgumentException("speed " + speed + " must lie in 0.1..100 (1 = real time)");
        }
        if (arena.robots().isEmpty()) {
            throw new IllegalArgumentException("arena " + arena.name() + " has no robot start pose; add a 'robot' line");
        }
        this.arena = arena;
        this.settings = settings;
        this.speed = speed;
        this.engine = new Engine(new World(arena), seed);
        this.robot = engine.addRobot("served", arena.robots().get(0), settings);
        robot.onBoard().servedDirectly();
        this.timing = robot.link();
    }

    /**
     * Add a snapshot listener (a window, a recorder). Call before {@link #start()}; it is called on
     * the engine thread, holding the robot's lock: keep it short.
     *
     * @param listener receives snapshots
     * @param periodNanos how often, a whole number of 1 ms ticks
     */
    public void addListener(SnapshotListener listener, long periodNanos) {
        lock.lock();
        try {
            engine.addListener(listener, periodNanos);
        } finally {
            lock.unlock();
        }
    }

    /** Start the engine thread: simulated time starts now. */
    public synchronized void start() {
        if (ticker != null) {
            throw new IllegalStateException("the served robot is already running");
        }
        running = true;
        wallStart = System.nanoTime();
        ticker = new Thread(this::tickLoop, "served-robot-engine");
        ticker.setDaemon(true);
        ticker.start();
    }

    /**
     * Keep the robot's time from running more than {@code leadNanos} of simulated time past the
     * last command a client sent: a client starved of the processor (a busy test machine) then finds
     * the robot where it left it instead of far ahead. A real robot does not wait, so this is off
     * by default; tests that compare a run through the server with a direct one at a high speed
     * factor use it.
     *
     * @param leadNanos the most simulated time the robot may run ahead of the client, ns; 0 = off
     */
    public void followClient(long leadNanos) {
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
                // The client is late: hold the robot's time, and resume the pacing from here.
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
            LockSupport.parkNanos(TICK_PERIOD_NANOS);
        }
    }

    /**
     * Answer one command as the robot would, at this instant of simulated time.
     *
     * @param command a parsed command
     * @return the reply line, without CR LF
     */
    public String execute(Command command) {
        lock.lock();
        try {
            lastCommandNanos = engine.timeNanos();
            return answer(command);
        } finally {
            lock.unlock();
        }
    }

    private String answer(Command command) {
        if (command instanceof Command.SetSpeed c) {
            robot.onBoard().driveSpeeds(c.left(), c.right());
            return c.reply().encode();
        } else if (command instanceof Command.ReadProximity c) {
            robot.onBoard().readProximity(values);
            return c.reply(values).encode();
        } else if (command instanceof Command.ReadLight c) {
            robot.onBoard().readLight(values);
            return c.reply(values).encode();
        } else if (command instanceof Command.ReadPositionCounters c) {
            return c.reply(robot.onBoard().counterLeft(), robot.onBoard().counterRight()).encode();
        } else if (command instanceof Command.SetPositionCounters c) {
            robot.onBoard().setCounters(c.left(), c.right());
            return c.reply().encode();
        } else if (command instanceof Command.ReadSpeed c) {
            return c.reply(robot.speedLeft(), robot.speedRight()).encode();
        } else if (command instanceof Command.MoveToPosition c) {
            robot.onBoard().moveToPositions(engine.timeNanos(), c.left(), c.right());
            return c.reply().encode();
        } else if (command instanceof Command.SetPositionProfile c) {
            robot.onBoard().positionProfile(c.maxSpeedLeft(), c.accelerationLeft(), c.maxSpeedRight(), c.accelerationRight());
            return c.reply().encode();
        } else if (command instanceof Command.ReadMotionStatus c) {
            return c.reply(robot.onBoard().motionStatus()).encode();
        } else if (command instanceof Command.SetPwm c) {
            robot.onBoard().drivePwm(c.left(), c.right());
            return c.reply().encode();
        } else if (command instanceof Command.SetLed c) {
            robot.onBoard().setLed(c.led(), c.action());
            return c.reply().encode();
        } else if (command instanceof Command.ReadVersion c) {
            return c.reply(BIOS_VERSION, PROTOCOL_VERSION).encode();
        } else if (command instanceof Command.SetSpeedPid c) {
            speedPid[0] = c.kp();
            speedPid[1] = c.ki();
            speedPid[2] = c.kd();
            return c.reply().encode();
        } else if (command instanceof Command.SetPositionPid c) {
            positionPid[0] = c.kp();
            positionPid[1] = c.ki();
            positionPid[2] = c.kd();
            return c.reply().encode();
        } else if (command instanceof Command.ReadAnalog c) {
            // No analog channel is modelled: every channel reads 0.
            return c.reply(0).encode();
        } else if (command instanceof Command.ReadBus c) {
            return c.reply(bus[c.address()]).encode();
        } else if (command instanceof Command.WriteBus c) {
            bus[c.address()] = c.data();
            return c.reply().encode();
        } else if (command instanceof Command.Turret c) {
            return turret(c);
        }
        throw new IllegalStateException("no answer for command " + command.encode());
    }

    private String turret(Command.Turret c) {
        if (c.id() != Command.Turret.GRIPPER) {
            return KheperaProtocol.COMMAND_NOT_FOUND;
        }
        TurretCommand body = c.body();
        if (body instanceof TurretCommand.Fingers f) {
            robot.onBoard().moveFingers(engine.timeNanos(), f.close() ? GripperState.CLOSED : GripperState.OPEN);
            return c.reply().encode();
        } else if (body instanceof TurretCommand.Arm a) {
            robot.onBoard().moveArm(engine.timeNanos(), a.position());
            return c.reply().encode();
        } else if (body instanceof TurretCommand.Resistivity) {
            return c.reply(robot.gripper().resistivity()).encode();
        } else if (body instanceof TurretCommand.Barrier) {
            return c.reply(robot.gripper().objectPresent() ? BARRIER_BROKEN : 0).encode();
        } else if (body instanceof TurretCommand.MotorPosition m) {
            return c.reply(m.motor() == 1 ? robot.gripper().armPosition()
                    : robot.gripper().fingers() == GripperState.CLOSED ? FINGERS_CLOSED_POSITION : 0).encode();
        } else if (body instanceof TurretCommand.Version) {
            return c.reply(GRIPPER_VERSION).encode();
        }
        return KheperaProtocol.COMMAND_NOT_FOUND;
    }

    /** @return the speed PID gains last set by {@code A} (stored; the simulated wheels ignore them) */
    public int[] speedPid() {
        return speedPid.clone();
    }

    /** @return the position PID gains last set by {@code F} (stored; the position mode ignores them) */
    public int[] positionPid() {
        return positionPid.clone();
    }

    /** The client has gone: stop the wheels at once and leave position mode (LEDs stay as they are). */
    public void stopWheels() {
        lock.lock();
        try {
            robot.emergencyStop();
        } finally {
            lock.unlock();
        }
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

    /**
     * Run code against the robot between ticks, holding the lock (tests, tools).
     *
     * @param action what to do
     * @param <T> its result's type
     * @return its result
     */
    public <T> T inspect(java.util.function.Function<SimRobot, T> action) {
        lock.lock();
        try {
            return action.apply(robot);
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

    /** @return the link timing replies are paced by (the settings' baud and turnaround) */
    public LinkTiming timing() {
        return timing;
    }

    /** @return the arena served */
    public Arena arena() {
        return arena;
    }

    /** @return the settings the robot was built with */
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
