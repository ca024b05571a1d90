package org.kheperasim.sim.host;

import java.util.List;
import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.binding.Controllers;
import org.kheperasim.sim.engine.RobotDriver;
import org.kheperasim.sim.engine.SimRobot;

/**
 * One controller's life in a run: it is constructed, started when the engine first gives it the
 * turn, and ends by returning, throwing, hanging or being stopped; whichever way, its robot stops
 * (as robot-link sends {@code D,0,0}) and the run goes on. Its time is kept by its
 * {@link ControllerClock}; its robot is the {@link SimulatedRobotPort} behind its API; the turn is
 * passed by the {@link Lockstep}.
 *
 * <p>A controller that runs for {@code hangTimeout} of real time without an API call is reported by
 * name with the simulated time, and stopped; the engine never hangs on it.
 */
public final class ControllerHost implements HostedController {

    private static final long STOP_GRACE_MILLIS = 2_000;

    private final SimRobot robot;
    private final Class<?> type;
    private final String name;
    private final ConsoleSink console;
    private final ControllerClock clock;
    private final ControllerThreads threads = new ControllerThreads();
    private final Thread controller;
    private Lockstep lockstep;
    /** Its life: started, stopping, ended, and why; the only record of it (see {@link ControllerLife}). */
    private final ControllerLife life = new ControllerLife();
    private final StrayThreads strays = new StrayThreads(this);
    /** The thread constructing the controller, while it does; threads started then join the lockstep. */
    private volatile Thread constructing;
    /**
     * Set when the controller is asked to stop the Appendix's way: its own thread calls its
     * {@code killControl()} at its next API call or loop, holding the turn, just before it unwinds
     * (never the run's owner or another thread of the simulator's, see {@link #checkStop}).
     */

    /**
     * Construct the controller (it does not start until the engine first runs it).
     *
     * @param robot the simulated robot it drives
     * @param type the controller class, loaded through a controller class loader
     * @param console where its messages and errors go
     * @param options hang timeout and test jitter
     */
    public ControllerHost(SimRobot robot, Class<?> type, ConsoleSink console, HostOptions options) {
        this.robot = robot;
        this.type = type;
        // The robot's name: the simple class name alone, and with its index (Name#3) when the arena has several.
        this.name = robot.name();
        this.console = console;
        this.clock = new ControllerClock(this, threads, robot.model().link().apiCostNanos(), options.jitterMaxMicros());
        SimulatedRobotPort port = new SimulatedRobotPort(robot, clock);
        // The clock is inheritable: binding it while the controller's Thread object is constructed
        // gives it to the controller thread, and only to it. The caller's own clock, if it has one
        // (a run built on a controller's thread), is put back afterwards.
        SimClock.Clock outer = SimClock.current();
        SimClock.bind(clock);
        constructing = Thread.currentThread();
        Thread created;
        try {
            created = ConstructionWatch.construct(name, type, options.hangTimeoutNanos(),
                    () -> Controllers.instantiate(type, new CurrentRobotState(port), new MessagePasser(port)));
        } finally {
            constructing = null;
            SimClock.bind(outer);
        }
        controller = created;
        threads.main(created);
        threads.main().chooseRunner(clock, ThreadRunners.contained(type), (t, e) -> ended(e));
        for (Participant p : threads.all()) {
            if (p.index > 0) {
                prepare(p);
            }
        }
    }

    /**
     * @return the controller's name in messages: its simple class name, with its robot's index when there are several
     *     (Name#3)
     */
    public String name() {
        return name;
    }

    /** @return the controller class */
    public Class<?> type() {
        return type;
    }

    /** @return where the controller is in its life */
    public ControllerStatus status() {
        return life.status();
    }

    /** @return what the controller threw, or null */
    public Throwable failure() {
        return life.failure();
    }

    // ------------------------------------------------------------------ the turn

    @Override
    public long wakeNanos() {
        return life.status().ended() ? Long.MAX_VALUE : clock.wake();
    }

    @Override
    public void grant(long limitNanos) {
        clock.grant(limitNanos);
    }

    /** Join a run: the lockstep that passes this host the turn. */
    void join(Lockstep lockstep) {
        this.lockstep = lockstep;
    }

    Lockstep lockstep() {
        return lockstep;
    }

    /** @return the thread of this controller's that waits on {@code seat}, or null */
    Participant participantAt(Turn.Seat seat) {
        return threads.at(seat);
    }

    /** @return API calls made so far; read without synchronisation by the watchdog */
    long apiCalls() {
        return clock.apiCalls();
    }

    /** Give this host the turn, from whichever thread holds it: start the controller, or wake it. */
    void receiveTurn(Turn turn) {
        life.on(ControllerLife.Event.START);
        clock.runNext();
    }

    /**
     * The controller broke a rule (see {@link Containment}): report it once, and stop the
     * controller; its thread unwinds from the call that broke it.
     */
    void brokeRule(String what) {
        fault(ControllerStatus.BROKE_RULE, what + "; the controller was stopped and the robot's motors set to 0");
    }

    /** The controller allocates without bound: stop it, and let what it holds go. */
    void exceededMemory(String what) {
        // Stopped before the message is made: a controller filling the heap must not go on meanwhile.
        if (life.on(ControllerLife.Event.FAULT, ControllerStatus.EXCEEDED_MEMORY)) {
            try {
                report("allocated without bound (" + what + "); the controller was stopped and the robot's motors set"
                        + " to 0. Does it keep adding to a list or map it never empties?");
            } catch (OutOfMemoryError full) {
                HeapWatch.ranOut();
                report("allocated without bound (the Java heap was full); the controller was stopped.");
            }
        }
    }

    /** The first fault decides how the controller ends, and is the one reported. */
    private void fault(ControllerStatus end, String message) {
        if (life.on(ControllerLife.Event.FAULT, end)) {
            report(message);
        }
    }

    private void report(String message) {
        say(ConsoleLine.Kind.ERROR, "controller " + name + " (" + type.getName() + ") " + message);
        strays.interrupt();
    }

    /**
     * A thread the controller started from a thread outside the lockstep (a timer's, its window's
     * event thread): it runs on the wall clock, and ends with the run. Started here.
     */
    void adoptStray(Thread t) {
        strays.start(t, ThreadRunners.contained(type));
    }

    /** @return true on the thread constructing the controller, while it does */
    boolean constructing() {
        return Thread.currentThread() == constructing;
    }

    /** A thread the controller's code started: it takes part in the lockstep, and ends with the controller. */
    void prepare(Participant p) {
        p.chooseRunner(clock, ThreadRunners.contained(type), (th, e) -> helperDied(p, e));
    }

    /** A thread the controller started threw: it ends (the controller goes on), and the turn goes back to the owner. */
    private void helperDied(Participant p, Throwable e) {
        String message = ControllerFailures.helperThrew("thread " + p + " that the controller started", e);
        if (message != null) {
            say(ConsoleLine.Kind.ERROR, message);
        }
        Turn turn = lockstep.turn();
        if (turn.heldBy(p.seat)) {
            helperEnded(p);
            lockstep.passTo(null);
        }
    }

    /** The watchdog saw a thread the controller started end while it held the turn: its run() returned. */
    void helperReturned(Participant p) {
        helperEnded(p);
    }

    /**
     * A thread the controller started has ended, holding the turn. If every thread left waits for
     * another (the one that ended was to notify them), nothing can run again: a deadlock.
     */
    private void helperEnded(Participant p) {
        threads.ended(p);
        if (threads.deadlocked()) {
            deadlocked(threads.describeWaits());
        }
    }

    /** Every thread of the controller waits for another: nothing can ever run again. Called holding the turn. */
    void deadlocked(String waits) {
        if (life.on(ControllerLife.Event.DEADLOCKED)) {
            say(ConsoleLine.Kind.ERROR, "controller " + name + " (" + type.getName() + ") is deadlocked: " + waits
                    + ". The controller was stopped and the robot's motors set to 0.");
            afterEnd();
        }
    }

    /**
     * Unwind the controller's thread when it has been asked to stop. Asked the Appendix's way (the
     * run's end, the user's Stop, a hang), the controller's own thread first calls its
     * {@code killControl()}, once: the controller's code on the controller's thread, holding the
     * turn and watched like the rest of its code (what it throws is ignored; if it never returns,
     * the controller is left behind as one that ignores the stop).
     */
    void checkStop() {
        if (life.stopRequested()) {
            if (Thread.currentThread() == threads.main().runner && life.takeKill()) {
                Controllers.requestStop(controller);
            }
            throw new ControllerStoppedError("controller " + name + " was stopped");
        }
    }

    // ------------------------------------------------------------------ the end of its life

    /**
     * Stop the controller: its thread is given the turn, calls its {@code killControl()} and
     * unwinds (see {@link #checkStop}). Returns when the thread has ended, or after a grace
     * period (the controller is then detached and reported). Called by the run's owner.
     */
    void stop() {
        // The owner holds the turn: the controller cannot start meanwhile.
        if (life.state().phase() == ControllerLife.Phase.NOT_STARTED) {
            life.on(ControllerLife.Event.STOP);
            return;
        }
        if (!life.status().ended()) {
            life.wantKill();
            Controllers.endDoWorkLoop(controller);
            life.on(ControllerLife.Event.STOP);
            clock.switchTo(threads.main());
            lockstep.awaitOwner(STOP_GRACE_MILLIS * 1_000_000L);
            // Its thread is let go before it is interrupted: if that ends it, it must not pass the turn.
            if (life.on(ControllerLife.Event.LEFT_BEHIND)) {
                threads.main().interrupt();
                say(ConsoleLine.Kind.ERROR, "did not stop within " + STOP_GRACE_MILLIS / 1000 + " s of being asked;"
                        + " it was left behind. Does it catch Throwable, or loop inside a library call?");
                afterEnd();
            }
        }
        endThreads();
        life.signalStop();
        strays.end(STOP_GRACE_MILLIS);
    }

    /** @return true when the controller has ended but threads it started still live: the owner ends them */
    boolean threadsOutliveIt() {
        if (!life.status().ended() || threads.single()) {
            return false;
        }
        for (Participant p : threads.all()) {
            if (p.index > 0 && !p.done) {
                return true;
            }
        }
        return false;
    }

    /**
     * The threads the controller started end with it: each in turn is given the turn, sees the stop
     * and unwinds. Called by the run's owner, once the controller's own thread has ended.
     */
    void endThreads() {
        if (threads.single()) {
            return;
        }
        life.signalStop();
        for (Participant p : threads.all()) {
            // The controller's own thread was left behind, or has ended: past its uncaught-exception
            // handler it only unwinds its last frames, and may still look alive for a moment.
            if (p.done || (p.index == 0
                    && (life.state().abandoned() || life.isOwnThreadOver() || !p.runner.isAlive()))) {
                continue;
            }
            if (!p.started || !p.runner.isAlive()) {
                threads.ended(p);
                continue;
            }
            clock.switchTo(p);
            lockstep.awaitOwner(STOP_GRACE_MILLIS * 1_000_000L);
            if (lockstep.takeBack(p.seat)) {
                p.interrupt();
                say(ConsoleLine.Kind.ERROR, "thread " + p + " that the controller started did not end with it; it"
                        + " was left behind. Does it catch Throwable, or loop inside a library call?");
            }
            threads.ended(p);
        }
    }

    /** The watchdog saw the controller's thread end while it held the turn: run() returned. */
    void returned() {
        if (life.on(ControllerLife.Event.UNWOUND, ControllerStatus.FINISHED)) {
            afterEnd();
        }
    }

    /** The watchdog saw no progress for the hang timeout while this controller held the turn. */
    void hung(Participant who, double realSeconds) {
        String thread = who.index == 0 ? "" : " (in thread " + who + " that it started)";
        boolean returnsAtOnce = who.index == 0 && doWorkReturnsAtOnce(realSeconds);
        say(ConsoleLine.Kind.ERROR, ControllerFailures.hung(name + " (" + type.getName() + ")", clock.now(), thread,
                realSeconds, returnsAtOnce));
        if (who.index == 0) {
            // Let go before it is interrupted: if that ends it, it must not pass the turn.
            life.wantKill();
            Controllers.endDoWorkLoop(controller);
            boolean ends = life.on(ControllerLife.Event.HUNG);
            threads.main().interrupt();
            if (ends) {
                afterEnd();
            }
        } else {
            // It unwinds at its next loop checkpoint; the controller's other threads end with it.
            boolean ends = life.on(ControllerLife.Event.HELPER_HUNG);
            who.interrupt();
            threads.ended(who);
            if (ends) {
                afterEnd();
            }
        }
    }

    /**
     * Is the hung controller a {@link org.kheperasim.api.Controller} whose {@code doWork()} keeps
     * returning without a robot call (an empty one, say), rather than looping inside? Looked at on the
     * way to reporting it hung, until its {@code doWork()} returns once more, for half the time it has
     * been stalled (0.05 to 1 s): a loaded machine (load 30 on 2 cores) may not run its thread at all
     * for tens of milliseconds, and a fixed 50 ms then told an empty {@code doWork()} about a loop.
     *
     * @param stalledSeconds real time it has gone without progress
     */
    private boolean doWorkReturnsAtOnce(double stalledSeconds) {
        long before = Controllers.doWorkRounds(controller);
        if (before < 0) {
            return false;
        }
        long deadline = System.nanoTime()
                + (long) (StrictMath.min(1.0, StrictMath.max(0.05, stalledSeconds / 2)) * 1e9);
        while (System.nanoTime() < deadline) {
            java.util.concurrent.locks.LockSupport.parkNanos(2_000_000L);
            if (Controllers.doWorkRounds(controller) != before) {
                return true;
            }
        }
        return false;
    }

    /**
     * The run is being stopped while this controller holds the turn without progress: it unwinds at its next loop or
     * call.
     */
    void stopSoon() {
        // Its own thread calls its killControl() when it sees the stop, at its next loop or call; asked
        // again (every watch period while it makes no progress), it is not asked twice.
        if (life.state().phase() == ControllerLife.Phase.RUNNING) {
            life.wantKill();
            Controllers.endDoWorkLoop(controller);
        }
        life.on(ControllerLife.Event.STOP);
    }

    /** The controller has just ended: its robot stops, and it never needs the turn again. */
    private void afterEnd() {
        robot.emergencyStop();
        clock.ended();
    }

    /** The controller thread is ending with an exception (the uncaught-exception handler). */
    private void ended(Throwable e) {
        // Its end touches the robot and the turn: the simulator's code, which the watchdog never interrupts.
        boolean taken = threads.main().seat.enterSimulator() == Turn.TAKEN;
        boolean abandoned = taken || life.state().abandoned();
        life.ownThreadOver();
        if (abandoned) {
            return; // it no longer holds the turn
        }
        ControllerStatus end = ControllerStatus.STOPPED; // a fault deciding the end overrides it
        if (life.state().reason() == null) {
            if (e instanceof OutOfMemoryError) {
                HeapWatch.ranOut(); // before the message is made
            }
            ControllerFailures.Verdict v =
                    ControllerFailures.verdictOrUnreadable(e, "controller " + name + " (" + type.getName() + ")");
            if (v.message() != null) {
                life.failedWith(e);
                say(ConsoleLine.Kind.ERROR, v.message());
            }
            end = v.status();
        }
        if (life.on(ControllerLife.Event.UNWOUND, end)) {
            afterEnd();
        }
        lockstep.passTo(null);
    }

    /** A line for the console, stamped with the controller's simulated time. */
    void say(ConsoleLine.Kind kind, String text) {
        if (kind == ConsoleLine.Kind.ERROR) {
            life.error(text);
        }
        console.accept(new ConsoleLine(clock.now(), name, kind, text));
    }

    @Override
    public String lastError() {
        return life.lastError();
    }
}
