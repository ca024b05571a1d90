package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.file.Path;
import java.util.Locale;
import org.kheperasim.sim.commandlog.CommandLogWriter;
import org.kheperasim.sim.commandlog.LogChannel;
import org.kheperasim.sim.commandlog.LogHeader;
import org.kheperasim.sim.grade.worker.WorkerLoop;
import org.kheperasim.sim.grade.worker.WorkerRun;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.RunSession;

/**
 * A graded run's side of the grading, in the child JVM ({@link GradedRun}): it
 * connects to the grader's channel before any controller class is loaded, writes the command log as
 * the run goes, and at the end hands over its own result and ends the JVM, whatever threads a
 * controller left running (a thread pool that spins would otherwise keep the JVM alive until the
 * grader's wall limit). It also ends the JVM when the grader goes away (its standard input, a pipe
 * from the grader, reaches its end: even after {@code kill -9} of the grader) and at its own
 * wall-clock limit. In a warm worker JVM ({@link WorkerRun}) the same run hands over the same log and
 * result, and says where it would have ended its JVM.
 */
public final class ChildSide {
    /** The exit status of a run that ended itself at its wall-clock limit (as timeout(1)). */
    public static final int WALL_LIMIT_EXIT = WorkerLoop.WALL_LIMIT_EXIT;
    /** The exit status of a run whose grader went away. */
    public static final int ORPHANED_EXIT = WorkerLoop.ORPHANED_EXIT;

    private final CommandLogWriter log;
    /** The run as a warm worker makes it, or null in a JVM of its own. */
    private final WorkerRun worker;

    private ChildSide(CommandLogWriter log, WorkerRun worker) {
        this.log = log;
        this.worker = worker;
    }

    /**
     * Connect to the grader and start watching it and the wall clock. In a warm worker JVM
     * ({@link WorkerRun#current}) the worker watches the grader and the wall clock for all its runs.
     *
     * @param socket      the grader's channel
     * @param wallSeconds the run's wall-clock limit, s (0: none)
     * @return the child's side
     * @throws IOException if the grader is not listening
     */
    public static ChildSide start(Path socket, double wallSeconds) throws IOException {
        WorkerRun run = WorkerRun.current();
        if (run != null) {
            return new ChildSide(new CommandLogWriter(run.connect(socket, wallSeconds)), run);
        }
        Writer w = LogChannel.connect(socket);
        ChildSide side = new ChildSide(new CommandLogWriter(w), null);
        daemon("khepera-grade-lifeline", () -> {
            // The grader never writes to our standard input: its end means the grader is gone.
            try {
                InputStream in = System.in;
                byte[] buf = new byte[256];
                while (in.read(buf) >= 0) {
                    // nothing is sent; keep reading until the end
                }
            } catch (IOException e) {
                // the pipe broke: the grader is gone as well
            }
            Runtime.getRuntime().halt(ORPHANED_EXIT);
        });
        if (wallSeconds > 0) {
            PrintStream err = System.err;
            daemon("khepera-grade-wall-limit", () -> {
                try {
                    Thread.sleep((long) (wallSeconds * 1000));
                } catch (InterruptedException e) {
                    return;
                }
                err.println(String.format(Locale.ROOT,
                        "khepera-sim: error: the run passed its wall-clock limit of %.0f s"
                        + " and ends itself (exit status %d)", wallSeconds, WALL_LIMIT_EXIT));
                err.flush();
                Runtime.getRuntime().halt(WALL_LIMIT_EXIT);
            });
        }
        return side;
    }

    /** @return the log the run's engine records into */
    public CommandLogWriter log() {
        return log;
    }

    /**
     * Write the log's header, once the run is set up.
     *
     * @param session      the run
     * @param endNanos     where it ends, simulated ns
     * @param sampleMillis its trace's sample period, ms
     */
    public void started(RunSession session, long endNanos, long sampleMillis) {
        log.start(LogHeader.of(session, endNanos, sampleMillis));
    }

    /**
     * Hand over the run's own result, then end the JVM with this status once the output is out; in
     * a warm worker, say the run is done with this status instead (the worker then makes its next run,
     * or is replaced when a controller of this one was stopped against its will).
     *
     * @param claimJson the run's result, one line of JSON
     * @param exit      the exit status
     * @param result    the run's result
     */
    public void finish(String claimJson, int exit, RunResult result) {
        int status = exit;
        try {
            log.finish(claimJson);
        } catch (IOException e) {
            System.err.println("khepera-sim: error: could not hand the run's command log to the grader: "
                    + e.getMessage());
            status = exit == 0 ? 1 : exit;
        }
        System.out.flush();
        System.err.flush();
        if (worker != null) {
            worker.done(status, stoppedAgainstItsWill(result));
            return;
        }
        Runtime.getRuntime().halt(status);
    }

    /** @return what makes a warm worker unfit for another run after this one, or null */
    private static String stoppedAgainstItsWill(RunResult result) {
        for (RunResult.RobotResult r : result.robots()) {
            if (r.status() == ControllerStatus.HUNG || r.status() == ControllerStatus.BROKE_RULE
                    || r.status() == ControllerStatus.EXCEEDED_MEMORY) {
                return "a controller " + r.status().name().toLowerCase(java.util.Locale.ROOT).replace('_', ' ')
                        + " and was stopped";
            }
        }
        return null;
    }

    private static void daemon(String name, Runnable r) {
        Thread t = new Thread(null, r, name, 0, false);
        t.setDaemon(true);
        t.start();
    }
}
