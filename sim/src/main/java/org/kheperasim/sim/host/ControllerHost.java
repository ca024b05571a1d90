package org.kheperasim.sim.host;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.time.Instant;
import java.util.Locale;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.kheperasim.api.ArmPosition;
import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.GripperState;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.spi.Controllers;
import org.kheperasim.api.spi.RobotPort;
import org.kheperasim.sim.engine.RobotDriver;
import org.kheperasim.sim.engine.SimRobot;

/**
 * Runs one controller thread in lockstep with the engine, and is the robot behind its API.
 *
 * <h2>The time model</h2>
 * The controller has its own simulated clock. Each API call costs {@code api.callCostUs} of
 * simulated time (that is how a busy loop makes time pass), {@code Thread.sleep(ms)} costs exactly
 * {@code ms}, and computing between calls costs nothing. The engine lets the controller run through
 * one tick's stretch of simulated time at a time; a call that would reach past the stretch steps the
 * world forward itself, on the controller's own thread, until a controller must run again (see
 * {@link Lockstep}). Exactly one thread holds the turn at any moment, so a run does not depend on
 * thread scheduling, machine speed or load.
 *
 * <p>With one robot the controller's thread never waits for another thread: it runs its code, then
 * the world, then its code again. Between several robots the turn is passed with a short spin, then
 * a park.
 * A controller that runs for {@code hangTimeout} of real time without an API call is reported by
 * name with the simulated time, and stopped; the engine never hangs on it.
 */
public final class ControllerHost implements RobotDriver, RobotPort, SimClock.Clock {

    /** Tuning of a host that is not part of the simulation's result. */
    public record Options(long hangTimeoutNanos, int jitterMaxMicros) {
        /** Defaults: a controller is hung after 5 s of real time without an API call; no jitter. */
        public static Options defaults() {
            return new Options(TimeUnit.SECONDS.toNanos(5), 0);
        }

        /** @param micros largest random real-time delay injected at hand-offs (tests of determinism) */
        public Options withJitter(int micros) {
            return new Options(hangTimeoutNanos, micros);
        }

        /** @param nanos real time without an API call after which a controller is hung */
        public Options withHangTimeout(long nanos) {
            return new Options(nanos, jitterMaxMicros);
        }
    }

    /** Robot time starts at the Appendix controller's creation date, so currentTimeMillis looks plausible. */
    private static final long EPOCH_MILLIS = Instant.parse("2001-07-27T11:06:00Z").toEpochMilli();
    private static final long STOP_GRACE_MILLIS = 2_000;

    private final SimRobot robot;
    private final Class<?> type;
    private final String name;
    private final long apiCostNanos;
    private final Options options;
    private final ConsoleSink console;
    private final CurrentRobotState state;
    private final MessagePasser messages;

    private final Thread controller;
    private Lockstep lockstep;
    private volatile boolean controllerWaiting;
    private long apiCalls;
    private volatile ControllerStatus status = ControllerStatus.NOT_STARTED;
    private volatile boolean stopRequested;
    private volatile boolean detached;
    private boolean stopAnnounced;
    private volatile Throwable failure;

    // The controller's clock; only the thread holding the turn touches it (the turn is volatile).
    private long now;
    private long limit;
    private long wake;

    /**
     * Construct the controller (it does not start until the engine first runs it).
     *
     * @param robot the simulated robot it drives
     * @param type the controller class, loaded through a controller class loader
     * @param console where its messages and errors go
     * @param options hang timeout and test jitter
     */
    public ControllerHost(SimRobot robot, Class<?> type, ConsoleSink console, Options options) {
        this.robot = robot;
        this.type = type;
        this.name = type.getSimpleName();
        this.console = console;
        this.options = options;
        this.apiCostNanos = StrictMath.max(1, (long) (robot.settings().number("api.callCostUs") * 1000));
        this.state = new CurrentRobotState(this);
        this.messages = new MessagePasser(this);
        // The clock is inheritable: binding it while the controller's Thread object is constructed
        // gives it to the controller thread, and only to it.
        SimClock.bind(this);
        Thread created;
        try {
            created = Controllers.instantiate(type, state, messages);
        } finally {
            SimClock.unbind();
        }
        controller = created;
        controller.setDaemon(true);
        controller.setUncaughtExceptionHandler((t, e) -> ended(e));
    }

    /** @return the controller's simple class name */
    public String name() {
        return name;
    }

    /** @return the controller class */
    public Class<?> type() {
        return type;
    }

    /** @return where the controller is in its life */
    public ControllerStatus status() {
        return status;
    }

    /** @return what the controller threw, or null */
    public Throwable failure() {
        return failure;
    }

    // ------------------------------------------------------------------ the turn

    @Override
    public long wakeNanos() {
        return status.ended() ? Long.MAX_VALUE : wake;
    }

    @Override
    public void grant(long limitNanos) {
        limit = limitNanos;
    }

    /** Join a run: the lockstep that passes this host the turn. */
    void join(Lockstep lockstep) {
        this.lockstep = lockstep;
    }

    /** @return the controller's thread */
    Thread thread() {
        return controller;
    }

    /** @return API calls made so far; read without synchronisation by the watchdog */
    long apiCalls() {
        return apiCalls;
    }

    /** Give this host the turn, from whichever thread holds it: start the controller, or wake it. */
    void receiveTurn() {
        if (status == ControllerStatus.NOT_STARTED) {
            status = ControllerStatus.RUNNING;
            controller.start();
        } else if (controllerWaiting) {
            LockSupport.unpark(controller);
        }
    }

    /** The controller's slice is used up: step the world on this thread until someone must run. */
    private void yieldTurn() {
        wake = now;
        jitter();
        RobotDriver next;
        try {
            next = lockstep.engine().advance();
        } catch (RuntimeException | Error e) {
            lockstep.engineFailed(e);
            next = null;
        }
        if (next == this) {
            return;
        }
        lockstep.passTo(next);
        awaitTurn();
        if (stopRequested) {
            throw new ControllerStoppedError("controller " + name + " was stopped");
        }
    }

    private void awaitTurn() {
        long spinStart = 0;
        int spins = 0;
        while (!lockstep.holds(controller)) {
            if (spins == 0) {
                spinStart = System.nanoTime();
            }
            if (Lockstep.spinning(++spins, spinStart)) {
                continue;
            }
            controllerWaiting = true;
            if (!lockstep.holds(controller)) {
                LockSupport.park(this);
            }
            controllerWaiting = false;
        }
    }

    /**
     * Stop the controller: call its {@code killControl()}, then unwind its thread (the owner gives
     * it the turn so that it sees the stop). Returns when the thread has ended, or after a grace
     * period (the controller is then detached and reported). Called by the run's owner.
     */
    void stop() {
        if (status == ControllerStatus.NOT_STARTED) {
            status = ControllerStatus.STOPPED;
            return;
        }
        if (status != ControllerStatus.RUNNING) {
            return;
        }
        announceStop();
        Controllers.requestStop(controller);
        lockstep.passTo(this);
        lockstep.awaitOwner(STOP_GRACE_MILLIS * 1_000_000L);
        if (status == ControllerStatus.RUNNING) {
            detached = true;
            controller.interrupt();
            say(ConsoleLine.Kind.ERROR, "did not stop within " + STOP_GRACE_MILLIS / 1000 + " s of being asked;"
                    + " it was left behind. Does it catch Throwable, or loop inside a library call?");
            finish(ControllerStatus.STOPPED);
        }
    }

    /** The watchdog saw the controller's thread end while it held the turn: run() returned. */
    void returned() {
        finish(ControllerStatus.FINISHED);
    }

    /** The watchdog saw no progress for the hang timeout while this controller held the turn. */
    void hung(double realSeconds) {
        say(ConsoleLine.Kind.ERROR, String.format(Locale.ROOT,
                "controller %s (%s) stopped making API calls at simulated time %.3f s: it ran for %.1f s of"
                        + " real time without reading a sensor, setting a motor or sleeping. A loop that waits for"
                        + " something must read a sensor or call Thread.sleep inside it. The controller was"
                        + " stopped and the robot's motors set to 0.",
                name, type.getName(), now / 1e9, realSeconds));
        detached = true;
        announceStop();
        Controllers.requestStop(controller);
        controller.interrupt();
        finish(ControllerStatus.HUNG);
    }

    private void announceStop() {
        stopRequested = true;
        if (!stopAnnounced) {
            stopAnnounced = true;
            SimClock.stopRequested();
        }
    }

    /** Called by whoever holds the turn. */
    private void finish(ControllerStatus end) {
        if (status.ended()) {
            return;
        }
        status = end;
        robot.emergencyStop();
        wake = Long.MAX_VALUE;
    }

    /** The controller thread is ending with an exception (the uncaught-exception handler). */
    private void ended(Throwable e) {
        if (detached) {
            settleStop();
            return;
        }
        if (e instanceof ControllerStoppedError) {
            finish(ControllerStatus.STOPPED);
        } else {
            failure = e;
            say(ConsoleLine.Kind.ERROR, "threw " + e + "; the robot was stopped.\n" + studentTrace(e));
            finish(ControllerStatus.FAILED);
        }
        settleStop();
        lockstep.passTo(null);
    }

    private void settleStop() {
        if (stopAnnounced) {
            SimClock.stopSettled();
        }
    }

    /** The stack trace down to the first frame of the simulator's own code: the student's part. */
    private static String studentTrace(Throwable e) {
        StringWriter out = new StringWriter();
        e.printStackTrace(new PrintWriter(out));
        StringBuilder kept = new StringBuilder();
        for (String line : out.toString().split("\\R")) {
            String t = line.trim();
            if (t.startsWith("at org.kheperasim.sim.") || t.startsWith("at java.base/java.lang.Thread.run")) {
                break;
            }
            if (t.startsWith("at java.base/jdk.internal.reflect.")) {
                continue;
            }
            kept.append(line).append('\n');
        }
        return kept.toString().stripTrailing();
    }

    private void say(ConsoleLine.Kind kind, String text) {
        console.accept(new ConsoleLine(now, name, kind, text));
    }

    private void jitter() {
        int max = options.jitterMaxMicros();
        if (max > 0 && ThreadLocalRandom.current().nextInt(8) == 0) {
            LockSupport.parkNanos(ThreadLocalRandom.current().nextLong(max * 1000L + 1));
        }
    }

    // ------------------------------------------------------------------ the controller's side

    /** Every API call starts here: the lockstep check. */
    private void enter() {
        Thread t = Thread.currentThread();
        if (t != controller) {
            if (status == ControllerStatus.NOT_STARTED) {
                return; // the controller's constructor looking around: free, no time passes
            }
            throw new IllegalStateException("the robot API was called from thread '" + t.getName() + "', not from"
                    + " the controller's own thread; in the simulator only the controller thread may use it"
                    + " (that keeps runs deterministic)");
        }
        if (stopRequested) {
            throw new ControllerStoppedError("controller " + name + " was stopped");
        }
        apiCalls++;
        if (now >= limit) {
            yieldTurn();
        }
    }

    private void leave() {
        now += apiCostNanos;
    }

    @Override
    public void sleepNanos(long nanos) throws InterruptedException {
        if (Thread.currentThread() != controller) {
            TimeUnit.NANOSECONDS.sleep(nanos);
            return;
        }
        if (stopRequested) {
            throw new ControllerStoppedError("controller " + name + " was stopped");
        }
        if (Thread.interrupted()) {
            throw new InterruptedException("sleep interrupted");
        }
        apiCalls++;
        now += StrictMath.max(nanos, apiCostNanos);
        if (now >= limit) {
            yieldTurn();
        }
    }

    @Override
    public long nanoTime() {
        if (Thread.currentThread() != controller) {
            return System.nanoTime();
        }
        enter();
        long t = now;
        leave();
        return t;
    }

    @Override
    public long currentTimeMillis() {
        if (Thread.currentThread() != controller) {
            return System.currentTimeMillis();
        }
        enter();
        long t = EPOCH_MILLIS + now / 1_000_000L;
        leave();
        return t;
    }

    @Override
    public void pause() {
        if (Thread.currentThread() != controller) {
            Thread.onSpinWait();
            return;
        }
        enter();
        leave();
    }

    @Override
    public void checkpoint() {
        if (stopRequested && Thread.currentThread() == controller) {
            throw new ControllerStoppedError("controller " + name + " was stopped");
        }
    }

    // ------------------------------------------------------------------ the robot behind the API

    @Override
    public int proximity(int index) {
        enter();
        int v = robot.visibleProximity(now, index);
        leave();
        return v;
    }

    @Override
    public int ambientLight(int index) {
        enter();
        int v = robot.visibleLight(now, index);
        leave();
        return v;
    }

    @Override
    public void setSpeeds(int left, int right) {
        enter();
        robot.commandSpeeds(now, left, right);
        leave();
    }

    @Override
    public int leftSpeed() {
        enter();
        int v = robot.askedLeft();
        leave();
        return v;
    }

    @Override
    public int rightSpeed() {
        enter();
        int v = robot.askedRight();
        leave();
        return v;
    }

    @Override
    public int leftPosition() {
        enter();
        int v = robot.visibleEncoderLeft(now);
        leave();
        return v;
    }

    @Override
    public int rightPosition() {
        enter();
        int v = robot.visibleEncoderRight(now);
        leave();
        return v;
    }

    @Override
    public void setPositions(int left, int right) {
        enter();
        robot.commandPositions(now, left, right);
        leave();
    }

    @Override
    public void setArm(ArmPosition position) {
        enter();
        robot.commandArm(now, position);
        leave();
    }

    @Override
    public ArmPosition armPosition() {
        enter();
        ArmPosition v = robot.gripper().armRest();
        leave();
        return v;
    }

    @Override
    public boolean armMoving() {
        enter();
        boolean v = robot.gripper().armMoving();
        leave();
        return v;
    }

    @Override
    public void setFingers(GripperState fingers) {
        enter();
        robot.commandFingers(now, fingers);
        leave();
    }

    @Override
    public GripperState fingers() {
        enter();
        GripperState v = robot.gripper().fingers();
        leave();
        return v;
    }

    @Override
    public boolean objectPresent() {
        enter();
        boolean v = robot.gripper().objectPresent();
        leave();
        return v;
    }

    @Override
    public int resistivity() {
        enter();
        int v = robot.gripper().resistivity();
        leave();
        return v;
    }

    @Override
    public void sleep(long millis) throws InterruptedException {
        if (millis < 0) {
            throw new IllegalArgumentException("sleep of " + millis + " ms: the time must not be negative");
        }
        sleepNanos(TimeUnit.MILLISECONDS.toNanos(millis));
    }

    @Override
    public void message(String text) {
        enter();
        say(ConsoleLine.Kind.MESSAGE, text);
        leave();
    }
}
