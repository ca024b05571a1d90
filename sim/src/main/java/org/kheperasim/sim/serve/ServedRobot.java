package org.kheperasim.sim.serve;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.ReentrantLock;
import org.kheperasim.api.GripperState;
import org.kheperasim.api.IrSensor;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.EpuckCommand;
import org.kheperasim.link.protocol.KheperaProtocol;
import org.kheperasim.link.protocol.TurretCommand;
import org.kheperasim.link.protocol.dialect.Dialect;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.engine.view.SnapshotListener;

/**
 * One simulated Khepera that answers the robot's serial protocol: a robot of a {@link ServedArena}
 * with no controller (the client is the controller). A lone robot is served by
 * {@link #ServedRobot(Arena, Settings, long, double)}, which makes an arena of its own for it.
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

    private final ServedArena world;
    private final SimRobot robot;
    private final LinkTiming timing;
    private final ReentrantLock lock;
    private final int[] bus = new int[256];
    private final int[] speedPid = {3800, 800, 100};
    private final int[] positionPid = {3000, 20, 4000};
    private final int[] values = new int[IrSensor.COUNT];

    /**
     * Serve the arena's first robot alone.
     *
     * @param arena the arena; its first robot pose is where the robot starts
     * @param settings sensor, motor and link settings ({@code link.baud} sets the reply pacing)
     * @param seed the seed of the robot's noise
     * @param speed simulated seconds per wall-clock second, 1 for real time (0.1..100)
     */
    public ServedRobot(Arena arena, Settings settings, long seed, double speed) {
        this(new ServedArena(arena, settings, seed, speed, 1), 0);
    }

    private ServedRobot(ServedArena world, int index) {
        this(world, world.simRobot(index));
    }

    /** A robot of a served arena. */
    ServedRobot(ServedArena world, SimRobot robot) {
        this.world = world;
        this.robot = robot;
        this.lock = world.lock();
        this.timing = robot.link();
    }

    /** @return the arena this robot is served in */
    public ServedArena world() {
        return world;
    }

    /**
     * Add a snapshot listener (a window, a recorder). Call before {@link #start()}; it is called on
     * the engine thread, holding the lock: keep it short.
     *
     * @param listener receives snapshots
     * @param periodNanos how often, a whole number of 1 ms ticks
     */
    public void addListener(SnapshotListener listener, long periodNanos) {
        world.addListener(listener, periodNanos);
    }

    /** Start the arena's engine thread (once for all its robots): simulated time starts now. */
    public void start() {
        world.start();
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
        world.followClient(leadNanos);
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
            world.commandSeen();
            return answer(command);
        } finally {
            lock.unlock();
        }
    }

    private String answer(Command command) {
        if (command instanceof EpuckCommand c) {
            return EpuckAnswers.answer(robot, c);
        } else if (command instanceof Command.SetSpeed c) {
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
            robot.onBoard().moveToPositions(world.timeHeld(), c.left(), c.right());
            return c.reply().encode();
        } else if (command instanceof Command.SetPositionProfile c) {
            robot.onBoard().positionProfile(c.maxSpeedLeft(), c.accelerationLeft(), c.maxSpeedRight(),
                    c.accelerationRight());
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
            robot.onBoard().moveFingers(world.timeHeld(), f.close() ? GripperState.CLOSED : GripperState.OPEN);
            return c.reply().encode();
        } else if (body instanceof TurretCommand.Arm a) {
            robot.onBoard().moveArm(world.timeHeld(), a.position());
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
        return world.snapshot();
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
        return world.timeNanos();
    }

    /** @return simulated seconds per wall-clock second */
    public double speed() {
        return world.speed();
    }

    /** @return the protocol this robot answers in (decided by {@link ServedArena#dialectFor}) */
    public Dialect dialect() {
        return world.dialectFor(robot);
    }

    /** @return the link timing replies are paced by (the settings' baud and turnaround) */
    public LinkTiming timing() {
        return timing;
    }

    /** @return the arena served */
    public Arena arena() {
        return world.arena();
    }

    /** @return the settings the robot was built with */
    public Settings settings() {
        return world.settings();
    }

    /** @return the run's seed */
    public long seed() {
        return world.seed();
    }

    /** Stop the arena's engine thread (for all its robots). */
    @Override
    public void close() {
        world.close();
    }
}
