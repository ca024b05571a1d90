package org.kheperasim.sim.grade.worker;

import java.io.IOException;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.file.Path;
import org.kheperasim.sim.commandlog.LogChannel;

/**
 * The run a warm worker JVM is making now, as the graded run's own side ({@code grade.ChildSide})
 * sees it: where a run in a JVM of its own connects its command log, arms its wall-clock limit and
 * ends its JVM, a run in a worker does the first two here and, instead of ending the JVM, marks
 * itself done on the worker's standard error with the exit status the JVM would have ended with.
 */
public final class WorkerRun {
    private static volatile WorkerRun current;

    private final WorkerProtocol.Request request;
    private final PrintStream err;
    private LogChannel.Connection log;
    private volatile long deadlineNanos = Long.MAX_VALUE;
    private volatile double wallSeconds;
    private volatile boolean done;
    private volatile String restart;

    WorkerRun(WorkerProtocol.Request request, PrintStream err) {
        this.request = request;
        this.err = err;
    }

    /** @return the run this worker JVM is making now, or null (not a worker, or between runs) */
    public static WorkerRun current() {
        return current;
    }

    static void setCurrent(WorkerRun run) {
        current = run;
    }

    /**
     * Connect the run's command log, and start its wall-clock limit, as a child JVM does first.
     *
     * @param socket      the grader's socket for this run
     * @param wallSeconds the run's wall-clock limit, s (0: none)
     * @return the log's writer
     * @throws IOException if the grader is not listening
     */
    public synchronized Writer connect(Path socket, double wallSeconds) throws IOException {
        log = LogChannel.open(socket);
        if (wallSeconds > 0) {
            this.wallSeconds = wallSeconds;
            deadlineNanos = System.nanoTime() + (long) (wallSeconds * 1e9);
        }
        return log.writer();
    }

    /**
     * The run has handed over its result: where a JVM of its own ends with {@code exit}, say so.
     *
     * @param exit       the exit status
     * @param restartWhy why the worker must not make another run after this one (a controller was
     *                   stopped against its will: hung, broke a rule, exceeded memory), or null
     */
    public void done(int exit, String restartWhy) {
        synchronized (this) {
            if (done) {
                return;
            }
            done = true;
            deadlineNanos = Long.MAX_VALUE;
            if (restartWhy != null) {
                restart = restartWhy;
            }
        }
        System.out.flush();
        err.println(new WorkerProtocol.Mark(WorkerProtocol.Kind.DONE, request.token(), request.index(),
                exit, "").line());
        err.flush();
    }

    /** The run ended without handing over its result: its log ends where it stands, as at a JVM's end. */
    synchronized void abortLog() {
        if (log != null) {
            log.abort();
        }
    }

    boolean isDone() {
        return done;
    }

    String restartReason() {
        return restart;
    }

    void restartBecause(String why) {
        if (restart == null) {
            restart = why;
        }
    }

    /**
     * @return when the run passes its wall-clock limit, {@link System#nanoTime()} ns; {@link Long#MAX_VALUE} for never
     */
    long deadlineNanos() {
        return deadlineNanos;
    }

    double wallSeconds() {
        return wallSeconds;
    }

    WorkerProtocol.Request request() {
        return request;
    }
}
