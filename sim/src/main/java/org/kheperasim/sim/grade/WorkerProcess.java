package org.kheperasim.sim.grade;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HexFormat;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.commandlog.LogChannel;
import org.kheperasim.sim.grade.worker.WorkerProtocol;
import org.kheperasim.sim.sandbox.Box;
import org.kheperasim.sim.sandbox.BoxLimits;

/**
 * A warm worker JVM as the grader sees it: one submission's runs, made one after another in one JVM
 * ({@link WorkerMain}, in the same box, with the same JVM options and limits as a run's own JVM), each
 * judged as a run in a JVM of its own is ({@link Verdict}): from its command log, received over a
 * socket of its own, its exit status and its standard error, which the worker marks per run
 * ({@link WorkerErr}). Nothing else the worker says counts, and nothing it says about one run can
 * change another submission's: it sees only its own submission.
 *
 * <p>A run that does not end within the wall-clock limit gets its worker killed (the run is then
 * "killed" as a child JVM was); a run that ends the worker (a crash, the heap exhausted past the heap
 * watch, a controller's {@code halt}) is judged by the worker's exit status; either way the grader
 * starts a new worker for the submission's next run. So does a worker that ends itself after a run
 * that left something behind ({@link org.kheperasim.sim.grade.worker.WorkerLoop}).
 */
final class WorkerProcess implements AutoCloseable {
    private static final SecureRandom TOKENS = new SecureRandom();

    /**
     * What a run left.
     *
     * @param killed true when the grader killed the worker at the run's wall-clock limit
     * @param exit   the run's exit status: the worker's mark, or the worker's own when it ended in the run
     * @param err    the run's standard error (its last 64 KiB)
     * @param ended  true when the worker ended in the run (it cannot make another)
     */
    record Made(boolean killed, int exit, String err, boolean ended) {
    }

    private final Process process;
    private final Writer requests;
    private final WorkerErr err;
    private final Tail out;
    private final Path folder;
    private final Path channels;
    private final boolean sandbox;
    private final Set<Process> running;
    private int made;
    private String restart;

    private WorkerProcess(Process process, Path folder, Path channels, boolean sandbox, Set<Process> running) {
        this.process = process;
        this.folder = folder;
        this.channels = channels;
        this.sandbox = sandbox;
        this.running = running;
        this.requests = new BufferedWriter(new OutputStreamWriter(process.getOutputStream(), StandardCharsets.UTF_8));
        this.err = new WorkerErr(process.getErrorStream(), "grade-worker-err-" + process.pid());
        this.out = new Tail(process.getInputStream(), 4096, "grade-worker-out-" + process.pid());
    }

    /**
     * Start a worker for a submission.
     *
     * @param sub     the submission (runnable)
     * @param arenas  the arenas its runs use (files are shown in the box)
     * @param robots  the most robots of those arenas
     * @param lim     the grading's limits
     * @param runs    the most runs it will make (its box's CPU time is theirs together)
     * @param slot    which of the grader's concurrent workers it is, from 0
     * @param folder  a new folder of the grader's own for its sockets (and, without the box, its scratch folder)
     * @param running the processes going now (a signal to the grader kills them)
     * @return the worker, starting
     * @throws IOException if it cannot be started
     */
    static WorkerProcess start(Submission sub, List<String> arenas, int robots, ChildRun.Limits lim, int runs, int slot,
            Path folder, Set<Process> running) throws IOException {
        Path channels = Files.createDirectories(folder.resolve("runs"));
        try {
            // The box's user may connect to the sockets the grader makes here, not list or add any.
            Files.setPosixFilePermissions(channels, PosixFilePermissions.fromString("rwx--x--x"));
        } catch (UnsupportedOperationException e) {
            // not POSIX: the grader's private folder keeps others out
        }
        Path scratch = Files.createDirectories(folder.resolve("scratch"));
        List<String> java = new ArrayList<>(ChildRun.jvmOptions(lim));
        // For the worker's own code only (grade.worker.ThreadNumbering): controllers cannot reflect, the allowlist
        // refuses it.
        java.add(0, "--add-opens=java.base/java.lang=ALL-UNNAMED");
        if (!lim.sandbox()) {
            java.add("-Djava.io.tmpdir=" + scratch.toAbsolutePath());
        }
        java.addAll(List.of(WorkerMain.MAIN, "--classpath", sub.classpath().toString(), "--scratch",
                lim.sandbox() ? "/tmp" : scratch.toAbsolutePath().toString()));
        List<String> cmd = lim.sandbox()
                ? Box.command(new Box.Spec(ChildRun.boxed(sub, arenas), List.of(), null, channels, false,
                        BoxLimits.forWorker(lim.heapMb(), robots, lim.wallSeconds(), runs), slot), java)
                : ChildRun.unboxed(java);
        ProcessBuilder pb = new ProcessBuilder(cmd);
        if (!lim.sandbox()) {
            pb.directory(scratch.toFile()); // as the box's /tmp: emptied after each run
        }
        Process p = pb.start();
        running.add(p);
        return new WorkerProcess(p, folder, channels, lim.sandbox(), running);
    }

    /**
     * A run the worker made, not judged yet.
     *
     * @param job         the run
     * @param child       what it left
     * @param trace       where the replay's trace goes
     * @param wallSeconds real time it took, s
     */
    record Received(GradePlan.Job job, Verdict.Child child, Path trace, double wallSeconds) {
    }

    /**
     * Make one run and judge it, as {@link ChildRun#run} does for a run in a JVM of its own.
     *
     * @param job   the run
     * @param sub   the submission
     * @param arena the arena
     * @param lim   the limits
     * @param runs  where the run's trace and log go
     * @return what came back
     * @throws IOException if its socket cannot be made, or the grading was interrupted
     */
    ChildRun.Outcome run(GradePlan.Job job, Submission sub, Arena arena, ChildRun.Limits lim,
            Path runs) throws IOException {
        return judge(make(job, sub, lim, runs), sub, arena, lim);
    }

    /**
     * Make one run, to be judged ({@link #judge}) while the worker makes the next.
     *
     * @param job   the run
     * @param sub   the submission
     * @param lim   the limits
     * @param runs  where the run's trace and log go
     * @return what came back
     * @throws IOException if its socket cannot be made, or the grading was interrupted
     */
    Received make(GradePlan.Job job, Submission sub, ChildRun.Limits lim, Path runs) throws IOException {
        Path trace = runs.resolve(ReportFiles.runId(job) + ".trace");
        Path logFile = runs.resolve(ReportFiles.runId(job) + ".log.gz");
        Files.deleteIfExists(trace);
        Files.deleteIfExists(logFile);
        Path socket = channels.resolve(job.index() + ".sock");
        long start = System.nanoTime();
        Made m;
        boolean cut;
        try (LogChannel.Receiver receiver = new LogChannel.Receiver(socket, logFile, Verdict.MAX_LOG_BYTES)) {
            Path seen = sandbox ? Box.CHANNELS.resolve(socket.getFileName()) : socket.toAbsolutePath();
            m = ask(job.index(), ChildRun.runArgs(job, sub, lim, seen), lim.wallSeconds());
            receiver.awaitEnd(10_000);
            cut = receiver.overLimit();
        }
        double wall = (System.nanoTime() - start) / 1e9;
        String madeIn = sandbox ? RunRecord.SANDBOX : RunRecord.NO_SANDBOX;
        Verdict.Child child = new Verdict.Child(m.killed(), m.exit(), ChildRun.strip(m.err(), sub),
                Files.isRegularFile(logFile) ? logFile : null, cut, madeIn);
        return new Received(job, child, trace, wall);
    }

    /**
     * Judge a run the worker made ({@link Verdict}), in the grader, with no worker involved.
     *
     * @param got   the run made
     * @param sub   the submission
     * @param arena the arena
     * @param lim   the limits
     * @return what came back
     */
    static ChildRun.Outcome judge(Received got, Submission sub, Arena arena, ChildRun.Limits lim) {
        Verdict.Judged judged = Verdict.judge(got.job(), sub, arena, lim, got.child(), got.trace());
        return new ChildRun.Outcome(judged.record(), got.wallSeconds(),
                Files.isRegularFile(got.trace()) ? got.trace() : null, got.child().log(),
                judged.page(), judged.tape(), judged.diverged());
    }

    /** Ask for one run and wait for its end, or its wall-clock limit (then kill the worker). */
    private Made ask(int index, List<String> args, double wallSeconds) throws IOException {
        byte[] t = new byte[16];
        TOKENS.nextBytes(t);
        String token = HexFormat.of().formatHex(t);
        err.expect(index, token);
        boolean first = made++ == 0;
        try {
            requests.write(new WorkerProtocol.Request(index, token, args).line() + "\n");
            requests.flush();
        } catch (IOException e) {
            // The worker has ended: what it left says why.
        }
        long deadline = System.nanoTime() + (long) (wallSeconds * 1e9);
        WorkerProtocol.Mark done;
        boolean killed = false;
        try {
            done = err.awaitDone((long) (wallSeconds * 1000));
            // Without its done mark the run ended the worker, or is still going at its wall-clock limit.
            if (done == null && !process.waitFor(StrictMath.max(0, deadline - System.nanoTime()),
                    TimeUnit.NANOSECONDS)) {
                killed = true;
                ChildRun.kill(process);
            }
        } catch (InterruptedException e) {
            ChildRun.kill(process);
            Thread.currentThread().interrupt();
            throw new IOException("grading was interrupted", e);
        }
        if (done != null) {
            return new Made(false, done.exit(), err.runText(0, false), false);
        }
        return new Made(killed, process.exitValue(), err.runText(5000, first), true);
    }

    /**
     * After a run (judged meanwhile): may the worker make another? It says so once it has put the JVM back
     * as a new run must find it; otherwise it is ended and must be replaced.
     *
     * @param millis how long to wait for it at most
     * @return true when it is ready for the next run
     */
    boolean ready(long millis) {
        WorkerProtocol.Mark m;
        try {
            m = process.isAlive() ? err.awaitNext(millis) : null;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            m = null;
        }
        if (m != null && m.kind() == WorkerProtocol.Kind.READY) {
            return true;
        }
        restart = m != null ? m.why() : process.isAlive() ? "no answer within " + millis / 1000 + " s after a run"
                : "it ended (exit status " + process.exitValue() + ")";
        return false;
    }

    /** @return why the worker was found unfit for another run, or null */
    String restartReason() {
        return restart;
    }

    /** @return the runs asked of it */
    int runs() {
        return made;
    }

    /** End the worker: the end of its standard input ends it; if it does not end soon, kill it. */
    @Override
    public void close() {
        try {
            requests.close();
        } catch (IOException e) {
            // it has ended already
        }
        try {
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                ChildRun.kill(process);
            }
        } catch (InterruptedException e) {
            ChildRun.kill(process);
            Thread.currentThread().interrupt();
        }
        running.remove(process);
        out.text(1000); // drained: standard output is no result of anything
        try (Stream<Path> s = Files.walk(folder)) {
            for (Path p : s.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        } catch (IOException e) {
            // a temporary folder left behind, inside the grader's own
        }
    }
}
