package org.kheperasim.link.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.kheperasim.link.robot.ControllerLoader;
import org.kheperasim.link.robot.Recorder;
import org.kheperasim.link.robot.RobotBackend;
import org.kheperasim.link.robot.RobotRun;
import org.kheperasim.link.robot.RobotSettings;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.tool.ControllerOptions;
import org.kheperasim.link.tool.ExitCodes;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code run}: a controller drives the robot. */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = "Run a controller on the robot until it ends, --seconds pass, or Ctrl-C."
        + " The robot is sent D,0,0 on every way out.")
final class RunCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Mixin
    Connection connection;

    @Mixin
    ControllerOptions controllerOptions = new ControllerOptions();

    @Option(names = "--record", paramLabel = "FILE", description = "Write the run to FILE (text): every poll cycle's"
            + " readings, and every line sent and received, with its time.")
    Path record;

    @Option(names = "--max-speed", defaultValue = "" + RobotSettings.DEFAULT_MAX_SPEED, paramLabel = "UNITS",
            description = "Speed clamp, 0..127 units of about 8 mm/s. Default: ${DEFAULT-VALUE}.")
    int maxSpeed;

    @Option(names = "--gripper", description = "A gripper turret is fitted: poll it and send its commands.")
    boolean gripper;

    @Option(names = "--park-gripper", description = "On stop, open the fingers and raise the arm (with --gripper).")
    boolean parkGripper;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        RobotSettings settings = RobotSettings.defaults().withMaxSpeed(maxSpeed).withGripper(gripper, parkGripper)
                .checkFor(connection.dialect());
        double seconds = controllerOptions.seconds(0);
        Class<?> type = new ControllerLoader(controllerOptions.classpath()).load(controllerOptions.controller());
        try (Session session = connection.open(out)) {
            Session.Versions v = session.open();
            out.println(CheckCommand.answers(session, v));
            out.println("running " + type.getName()
                    + (seconds > 0 ? " for " + seconds + " s" : " until it ends or Ctrl-C")
                    + "; speed clamp ±" + maxSpeed);
            out.flush();
            RobotBackend backend = new RobotBackend(session, settings, line -> {
                out.println(line);
                out.flush();
            });
            Recorder recorder = null;
            if (record != null) {
                recorder = new Recorder(record, "controller " + type.getName() + ", port " + connection.port
                        + ", " + connection.baud() + " baud, dialect " + session.dialect().name(), backend::startNanos);
                backend.onSample(recorder);
                session.transcript(recorder);
            }
            RobotRun run = new RobotRun(backend, type, line -> {
                out.println(line);
                out.flush();
            });
            // On SIGTERM or Ctrl-C the run is asked to stop, and the JVM waits (up to a grace) for the
            // lines below, which say whether the robot confirmed its stop: on the real robot that is
            // what the user needs to know. Given to the link, so a serial port is still open meanwhile.
            CountDownLatch reported = new CountDownLatch(1);
            Thread onSignal = new Thread(() -> {
                run.requestStop("stopped by a signal (SIGTERM or Ctrl-C)");
                try {
                    reported.await(REPORT_GRACE_SECONDS, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "khepera-link-report-on-exit");
            session.link().addExitHook(onSignal);
            RobotRun.Result r;
            try {
                try {
                    r = run.run((long) (seconds * 1000));
                } finally {
                    if (recorder != null) {
                        session.transcript(null);
                        recorder.close();
                    }
                }
                report(out, r);
            } finally {
                reported.countDown();
                session.link().removeExitHook(onSignal);
            }
            return exitStatus(r);
        }
    }

    /** How long the JVM, stopped by a signal, waits for the run's last lines before it exits, s. */
    private static final long REPORT_GRACE_SECONDS = 15;

    private void report(PrintWriter out, RobotRun.Result r) {
        out.println("ended: " + r.detail());
        out.println(String.format(Locale.ROOT, "poll rate %.1f cycles/s; %d exchanges, %d retries, %d lines skipped;"
                + " mean round trip %.2f ms", r.pollRateHz(), r.stats().exchanges(), r.stats().retries(),
                r.stats().skippedLines(), r.stats().meanRoundTripNanos() / 1e6));
        out.println(r.stopAcknowledged() ? "robot stopped (D,0,0 acknowledged)"
                : "D,0,0 was sent but not acknowledged: CHECK THE ROBOT HAS STOPPED");
        if (record != null) {
            out.println("recorded to " + record.toAbsolutePath());
        }
        if (r.failure() != null) {
            r.failure().printStackTrace(out);
        }
        out.flush();
    }

    /**
     * @param r how the run ended
     * @return the exit status: a failure, and any end whose stop the robot did not confirm, is not a
     *     success (a script must not move on while the robot may still be driving)
     */
    static int exitStatus(RobotRun.Result r) {
        if (!r.stopAcknowledged()) {
            return ExitCodes.FAILED;
        }
        return switch (r.end()) {
            case FINISHED, TIME_UP, STOPPED -> ExitCodes.OK;
            case FAILED, LINK_LOST -> ExitCodes.FAILED;
        };
    }
}
