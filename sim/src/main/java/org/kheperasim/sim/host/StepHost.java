package org.kheperasim.sim.host;

import java.util.concurrent.TimeUnit;
import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.StepController;
import org.kheperasim.api.binding.Controllers;
import org.kheperasim.sim.engine.SimRobot;

/**
 * A {@link StepController} in a run: the engine's turn holder calls its {@code step()} inline, once
 * per period, with no thread of the controller's and no hand-over, which is what makes swarms fast.
 * Its API calls cost the same simulated time and see the same serial-link timing as a thread-style
 * controller's; the next step comes one period after this one's last call.
 *
 * <p>A step that throws fails the controller (reported with the student's lines, the robot
 * stopped); one that sleeps breaks the step contract; one that runs for the hang timeout of real
 * time without returning is stopped at its next loop by the {@link StepWatchdog}.
 */
public final class StepHost implements HostedController, PortClock, StepWatchdog.Watched {
    private final SimRobot robot;
    private final Class<?> type;
    private final String name;
    private final ConsoleSink console;
    /**
     * The controller; let go (null) once it has been stopped for filling the heap, so that what it holds can be
     * collected.
     */
    private StepController controller;
    /** What runs now, for messages. */
    private volatile Part part = Part.STEP;
    private int steps;
    private final long periodNanos;
    private final long apiCostNanos;
    private final long hangTimeoutNanos;
    private final StepClock clock = new StepClock(this);
    /** Its life: started, stopping, ended, and why; the only record of it (see {@link ControllerLife}). */
    private final ControllerLife life = new ControllerLife();
    private long wake;
    private long now;
    /**
     * The number of the step running now, or {@link #NOT_STEPPING}; read by the watchdog. A number, not
     * the real time it began: reading the clock at each of a swarm's many thousand steps a second cost
     * more than the step of a simple controller. The watchdog times a step itself, from when it first
     * saw that number ({@link #seenStep}, {@link #seenSince}), so a hang is found within the hang timeout
     * and one or two of its looks (100 ms each).
     */
    private volatile long stepRunning = NOT_STEPPING;
    private static final long NOT_STEPPING = -1;
    /** Steps begun. */
    private long stepsBegun;
    /** The watchdog's own: the step it saw running at its last look, and the real time it first saw it (ns). */
    private long seenStep = NOT_STEPPING;
    private long seenSince;
    /** The run's stop request, asked by the watchdog while a step runs long (null: none). */
    private volatile java.util.function.BooleanSupplier runStop;
    /** While the run is being stopped, how long a step may run before it is stopped, ns. */
    private static final long STOP_PATIENCE_NANOS = 200_000_000L;

    /** The part of a step controller's code that runs, as messages name it. */
    private enum Part {
        SETUP("setup()"), STEP("step()");

        private final String text;

        Part(String text) {
            this.text = text;
        }

        @Override
        public String toString() {
            return text;
        }
    }

    /**
     * @param robot the robot it drives
     * @param type a step controller class, loaded through a controller class loader
     * @param console where its messages and errors go
     * @param options the hang timeout
     */
    public StepHost(SimRobot robot, Class<?> type, ConsoleSink console, HostOptions options) {
        this.robot = robot;
        this.type = type;
        // The robot's name: the simple class name alone, and with its index (Name#3) when the arena has several.
        this.name = robot.name();
        this.console = console;
        // On the robot's own processor a step is one instant (its calls read memory): steps come at a fixed rate.
        this.apiCostNanos = robot.runsOnBoard() ? 0 : robot.model().link().apiCostNanos();
        this.hangTimeoutNanos = options.hangTimeoutNanos();
        SimulatedRobotPort port = new SimulatedRobotPort(robot, this);
        this.controller = ConstructionWatch.construct(name, type, hangTimeoutNanos,
                () -> Controllers.instantiateStep(type, new CurrentRobotState(port), new MessagePasser(port)));
        this.periodNanos = TimeUnit.MILLISECONDS.toNanos(controller.period());
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public Class<?> type() {
        return type;
    }

    @Override
    public ControllerStatus status() {
        return life.status();
    }

    @Override
    public Throwable failure() {
        return life.failure();
    }

    @Override
    public long wakeNanos() {
        return life.status().ended() ? Long.MAX_VALUE : wake;
    }

    @Override
    public void grant(long limitNanos) {
        // A step runs whole: its calls may reach past the tick, as a thread-style controller's last call may.
    }

    /** Run one step (the first time, setup and a step), on the thread holding the turn. */
    void step() {
        now = StrictMath.max(now, wake);
        SimClock.Clock outer = SimClock.current();
        SimClock.bind(clock);
        stepRunning = stepsBegun++;
        // Watched from its first step to its end, not registered at every step.
        boolean first = life.on(ControllerLife.Event.START);
        if (first) {
            StepWatchdog.watch(this);
        }
        try {
            if (first) {
                part = Part.SETUP;
                controller.begin();
                part = Part.STEP;
            }
            controller.stepOnce();
            wake = now + periodNanos;
            // After every 16th step (a step makes few API calls, where a thread-style controller's are counted
            // for this look): a few native reads, unless the heap is past its threshold. A step that allocates
            // without bound between two looks is caught by the JVM's own threshold notification (HeapWatch).
            String full = (++steps & 15) == 0 ? HeapWatch.pressed() : null;
            if (full != null) {
                say(ConsoleLine.Kind.ERROR, "controller " + name + " allocated without bound (" + full + "); the"
                        + " controller was stopped and the robot's motors set to 0. Does it keep adding"
                        + " to a list or map it never empties?");
                end(ControllerStatus.EXCEEDED_MEMORY);
            }
        } catch (ControllerStoppedError e) {
            // Why it was stopped (a rule, a hang, the run's stop) is the life's reason already.
            end(ControllerStatus.STOPPED);
        } catch (OutOfMemoryError e) {
            HeapWatch.ranOut();
            life.failedWith(e);
            say(ConsoleLine.Kind.ERROR, "controller " + name + " allocated without bound: the Java heap ran out; the"
                    + " controller was stopped and the robot's motors set to 0");
            end(ControllerStatus.EXCEEDED_MEMORY);
        } catch (RuntimeException | Error e) {
            life.failedWith(e);
            say(ConsoleLine.Kind.ERROR,
                    "threw " + e + " in " + part + "; the robot was stopped.\n" + ControllerFailures.studentTrace(e));
            end(ControllerStatus.FAILED);
        } finally {
            stepRunning = NOT_STEPPING;
            if (outer == null) {
                SimClock.unbind();
            } else {
                SimClock.bind(outer);
            }
        }
    }

    /** The watchdog's look: a step running for the hang timeout is stopped at its next loop checkpoint. */
    @Override
    public boolean overdue(long nowNanos) {
        long running = stepRunning;
        if (running == NOT_STEPPING || life.state().phase() != ControllerLife.Phase.RUNNING) {
            seenStep = NOT_STEPPING;
            return false;
        }
        if (running != seenStep) {
            seenStep = running;
            seenSince = nowNanos;
            return false;
        }
        long started = seenSince;
        java.util.function.BooleanSupplier stop = runStop;
        if (stop != null && nowNanos - started > STOP_PATIENCE_NANOS && stop.getAsBoolean()) {
            // The run is being stopped (a signal, the window's Stop) while a step loops: it ends at its next loop.
            return life.on(ControllerLife.Event.STOP);
        }
        if (nowNanos - started > hangTimeoutNanos) {
            // Told before the step is stopped, so the message comes before the run's end.
            say(ConsoleLine.Kind.ERROR, String.format(java.util.Locale.ROOT, "controller %s (%s): %s did not return"
                    + " for %.1f s of real time at simulated time %.3f s; a step must read the sensors, set"
                    + " the motors and return (no loops that wait). The controller was stopped and the robot's"
                    + " motors set to 0.",
                    name, type.getName(), part, (nowNanos - started) / 1e9, now / 1e9));
            return life.on(ControllerLife.Event.FAULT, ControllerStatus.HUNG);
        }
        return false;
    }

    /** The step broke a rule (see {@link Containment}): it is stopped with a named fault. */
    void brokeRule(String what) {
        if (life.on(ControllerLife.Event.FAULT, ControllerStatus.BROKE_RULE)) {
            say(ConsoleLine.Kind.ERROR, "controller " + name + " (" + type.getName() + ") " + what
                    + "; the controller was stopped and the robot's motors set to 0");
        }
    }

    /** Checked at every loop back-edge of the step's code. */
    void checkpoint() {
        if (life.stopRequested()) {
            boolean hung = life.state().reason() == ControllerStatus.HUNG;
            throw new ControllerStoppedError("controller " + name + (hung ? " hung in " : " was stopped in ") + part);
        }
    }

    /** @param stop the run's stop request, asked by the watchdog while a step runs long (null: none) */
    void runStop(java.util.function.BooleanSupplier stop) {
        runStop = stop;
    }

    /** Its code is over: the life ends with {@code end} (or the fault that stopped it), the robot stops. */
    private void end(ControllerStatus end) {
        if (life.on(ControllerLife.Event.UNWOUND, end)) {
            robot.emergencyStop();
            if (life.status() == ControllerStatus.EXCEEDED_MEMORY) {
                controller = null;
            }
        }
        StepWatchdog.unwatch(this);
        life.ownThreadOver();
    }

    /**
     * The run is over: the controller stops where it is (as a thread-style one does at its next call; no cleanup runs).
     */
    void stop() {
        if (life.state().phase() == ControllerLife.Phase.NOT_STARTED) {
            life.on(ControllerLife.Event.STOP);
            return;
        }
        if (!life.status().ended()) {
            life.on(ControllerLife.Event.STOP);
            end(ControllerStatus.STOPPED);
        }
        StepWatchdog.unwatch(this);
    }

    // ------------------------------------------------------------------ the port's clock

    @Override
    public void enter() {
        boolean stepping = stepRunning != NOT_STEPPING;
        if (!stepping && life.state().phase() == ControllerLife.Phase.NOT_STARTED) {
            return; // the constructor looking around: free, no time passes
        }
        if (!stepping) {
            throw new IllegalStateException("the robot API of step controller " + name + " was called outside step()"
                    + " (from thread '" + Thread.currentThread().getName()
                    + "'); use it only in setup(), step() and cleanup()");
        }
        checkpoint();
    }

    @Override
    public void leave() {
        now += apiCostNanos;
    }

    @Override
    public long now() {
        return now;
    }

    @Override
    public void sleepNanos(long nanos) {
        throw new IllegalStateException("step controller " + name + " slept in " + part + ": a step must return instead"
                + " (the next step comes " + periodNanos / 1_000_000 + " ms after this one; change periodMillis() to"
                + " step less often)");
    }

    @Override
    public void say(ConsoleLine.Kind kind, String text) {
        if (kind == ConsoleLine.Kind.ERROR) {
            life.error(text);
        }
        console.accept(new ConsoleLine(now, name, kind, text));
    }

    @Override
    public String lastError() {
        return life.lastError();
    }
}
