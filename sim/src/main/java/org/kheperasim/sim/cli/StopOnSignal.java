package org.kheperasim.sim.cli;

import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.ToIntFunction;
import org.kheperasim.link.tool.ToolErrors;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.trace.LineFileWriter;

/**
 * Runs a simulation so that a signal that ends the JVM (SIGTERM, Ctrl-C, a controller's
 * {@code System.exit}) still ends the run properly: a shutdown hook asks the run to stop at its next
 * tick, then waits while the run finishes its trace and the result is reported.
 * Should the run not stop in time (a controller that holds on), the hook writes out the trace's
 * whole lines itself and says so. After kill -9 nothing runs, but the trace is readable anyway
 * ({@link LineFileWriter}).
 */
final class StopOnSignal {

    private StopOnSignal() {
    }

    /**
     * @param run            the configured run
     * @param hangTimeoutSec the controllers' hang timeout, s: how long a stop can take at worst
     * @param report         prints the result and returns the exit status
     * @return the exit status
     */
    static int run(Simulation.Builder run, double hangTimeoutSec, ToIntFunction<RunResult> report) {
        AtomicBoolean stop = new AtomicBoolean();
        CountDownLatch reported = new CountDownLatch(1);
        long graceMillis = (long) Math.min(60_000, hangTimeoutSec * 1000 + 2000);
        Thread hook = new Thread(() -> {
            stop.set(true);
            try {
                if (!reported.await(graceMillis, TimeUnit.MILLISECONDS)) {
                    LineFileWriter.flushAll();
                    System.err.println(ToolErrors.prefix("khepera-sim") + "stopped by a signal, but the run did not"
                            + " stop within " + graceMillis / 1000
                            + " s (a controller holds on), so there is no result;"
                            + " the trace holds every whole line written so far");
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "khepera-sim-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            RunResult result = run.stopWhen(stop::get).run();
            if (stop.get()) {
                System.err.println(ToolErrors.prefix("khepera-sim").replace("error: ", "") + String.format(Locale.ROOT,
                        "stopped at %.3f s simulated because the program is being shut down (SIGTERM, Ctrl-C or a"
                        + " System.exit); the result and the trace cover the run up to there",
                        result.simulatedSeconds()));
            }
            return report.applyAsInt(result);
        } finally {
            reported.countDown();
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException shuttingDown) {
                // The hook is running (the JVM is going down): it has just been told the run is over.
            }
        }
    }
}
