package org.kheperasim.link.robot;

import java.util.Locale;
import java.util.function.Consumer;
import org.kheperasim.api.CurrentRobotState;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.binding.Controllers;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.session.SessionException;

/**
 * Runs one controller on a real robot: starts polling, starts the controller thread, and stops the
 * robot ({@code D,0,0}) on every way out: the controller returns, throws, is stopped, runs out of
 * time, the link drops, or the JVM exits (a shutdown hook, so Ctrl-C too).
 */
public final class RobotRun {
    /** How a run ended. */
    public enum End {
        /** The controller's run() returned. */
        FINISHED,
        /** The time limit was reached. */
        TIME_UP,
        /** The controller threw. */
        FAILED,
        /** The link to the robot failed. */
        LINK_LOST,
        /** Someone asked the run to stop (Ctrl-C, the JVM exiting, {@link #requestStop}). */
        STOPPED
    }

    /**
     * @param end how the run ended
     * @param detail what happened, for the user
     * @param pollRateHz poll cycles per second reached
     * @param stats the session's counts and round-trip times
     * @param stopAcknowledged whether the robot acknowledged the final {@code D,0,0}
     * @param failure what the controller threw, or null
     */
    public record Result(End end, String detail, double pollRateHz, Session.Stats stats, boolean stopAcknowledged,
            Throwable failure) {
    }

    private static final long STOP_GRACE_MILLIS = 2000;

    private final RobotBackend backend;
    private final Class<?> type;
    private final Consumer<String> console;
    private volatile String stopReason;
    private volatile Throwable thrown;
    private final long startNanos = System.nanoTime();

    /**
     * @param backend the robot (not yet polling)
     * @param type a checked controller class
     * @param console where messages go, one line each
     */
    public RobotRun(RobotBackend backend, Class<?> type, Consumer<String> console) {
        this.backend = backend;
        this.type = type;
        this.console = console;
    }

    /** @param why ask the run to end, and say why */
    public void requestStop(String why) {
        stopReason = why;
    }

    private String stamp() {
        return String.format(Locale.ROOT, "[%8.3f s] ", (System.nanoTime() - startNanos) / 1e9);
    }

    /**
     * Run the controller until it ends, the time is up, the link fails or a stop is requested;
     * then stop the robot and the controller.
     *
     * @param maxMillis the time limit, ms; 0 for none
     * @return how it ended
     * @throws SessionException when polling cannot start (the robot does not answer); the robot has
     *     been sent {@code D,0,0}
     */
    public Result run(long maxMillis) throws SessionException, InterruptedException {
        String name = type.getSimpleName();
        Consumer<String> say = text -> console.accept(stamp() + name + ": " + text);
        Thread hook = new Thread(() -> {
            requestStop("the program is exiting (Ctrl-C?)");
            backend.stop();
        }, "khepera-stop-on-exit");
        backend.session().link().addExitHook(hook);
        try {
            RobotBackend b = backend;
            Thread controller = Controllers.instantiate(type, new CurrentRobotState(b), new MessagePasser(
                    new ForwardingMessages(b, say)));
            controller.setDaemon(true);
            // The controller's own methods run on a thread of their own (ControllerCalls): an override that
            // spins or blocks never holds this thread, which stops the robot.
            ControllerCalls.Outcome handler = ControllerCalls.call(name, STOP_GRACE_MILLIS, () ->
                    controller.setUncaughtExceptionHandler((t, e) -> {
                        if (!(e instanceof ControllerStoppedError)) {
                            thrown = e;
                        }
                    }));
            if (!handler.returned()) {
                say.accept("its setUncaughtExceptionHandler() did not return within " + STOP_GRACE_MILLIS / 1000 + " s;"
                        + " what it throws will not be told");
            }
            try {
                backend.start(10_000);
            } catch (SessionException e) {
                backend.stop();
                throw e;
            }
            ControllerCalls.Outcome started = ControllerCalls.call(name, STOP_GRACE_MILLIS, controller::start);
            if (started.thrown() != null) {
                thrown = started.thrown();
            } else if (!started.returned()) {
                say.accept("its start() did not return within " + STOP_GRACE_MILLIS / 1000 + " s");
            }
            long deadline = maxMillis > 0 ? System.nanoTime() + maxMillis * 1_000_000L : Long.MAX_VALUE;
            End end;
            String detail;
            while (true) {
                controller.join(20);
                if (!controller.isAlive()) {
                    end = thrown == null ? End.FINISHED : End.FAILED;
                    detail = thrown == null ? "the controller's run() returned"
                            : "the controller threw " + ControllerCalls.describe(name, thrown);
                    break;
                }
                if (backend.failure() != null) {
                    end = End.LINK_LOST;
                    detail = backend.failure().getMessage();
                    break;
                }
                if (stopReason != null) {
                    end = End.STOPPED;
                    detail = stopReason;
                    break;
                }
                if (System.nanoTime() >= deadline) {
                    end = End.TIME_UP;
                    detail = "the time limit of " + maxMillis / 1000.0 + " s was reached";
                    break;
                }
            }
            // Stop the wheels first: after this nothing more is sent, whatever the controller does.
            boolean acknowledged = backend.stop();
            if (controller.isAlive()) {
                long graceEnd = System.nanoTime() + STOP_GRACE_MILLIS * 1_000_000L;
                ControllerCalls.call(name, STOP_GRACE_MILLIS, () -> {
                    try {
                        Controllers.requestStop(controller);
                    } finally {
                        controller.interrupt();
                    }
                });
                controller.join(StrictMath.max(1, (graceEnd - System.nanoTime()) / 1_000_000L));
                if (controller.isAlive()) {
                    say.accept("did not stop within " + STOP_GRACE_MILLIS / 1000 + " s of being asked; it was left"
                            + " behind (the robot is already stopped)");
                }
            }
            if (thrown != null && end != End.FAILED) {
                say.accept("threw " + ControllerCalls.describe(name, thrown) + " while stopping");
            }
            return new Result(end, detail, backend.pollRateHz(), backend.session().stats(), acknowledged, thrown);
        } finally {
            backend.stop();
            backend.session().link().removeExitHook(hook);
        }
    }

    /** The controller's messages, stamped with the run's time. */
    private static final class ForwardingMessages extends DelegatingPort {
        private final Consumer<String> say;

        ForwardingMessages(RobotBackend backend, Consumer<String> say) {
            super(backend);
            this.say = say;
        }

        @Override
        public void message(String text) {
            say.accept(text);
        }
    }
}
