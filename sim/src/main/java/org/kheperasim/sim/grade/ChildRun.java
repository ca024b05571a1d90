package org.kheperasim.sim.grade;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.commandlog.LogChannel;
import org.kheperasim.sim.sandbox.Box;
import org.kheperasim.sim.sandbox.BoxLimits;
import org.kheperasim.sim.sandbox.ClassArchive;
import org.kheperasim.sim.sandbox.OwnClasspath;
import org.kheperasim.sim.web.RunOutcome;
import org.kheperasim.sim.web.RunPageRecorder;

/**
 * Makes one graded run in a child JVM: {@code java -Xmx… -cp SIMULATOR GradedRun … --command-log SOCKET}
 * (the simulator's classpath at its real location, {@link OwnClasspath}: the child runs in another folder), in the
 * operating-system sandbox ({@link Box}) unless the grading said
 * {@code --no-sandbox}, with the heap limit, the simulated-time limit and a wall-clock limit after
 * which the child is killed (and at which it also ends itself). The child hands its command log
 * over the socket ({@link LogChannel}); standard input is a pipe the grader never writes to, whose end
 * tells the child its grader is gone. {@link Verdict} judges what came back.
 */
final class ChildRun {
    /**
     * What every run of a grading shares.
     *
     * @param heapMb       each run's heap, MiB
     * @param wallSeconds  each run's wall-clock limit, s
     * @param hangSeconds  the hang timeout, s
     * @param seconds      simulated seconds per run, or null for each arena's own
     * @param sampleMillis the trace's sample period, ms
     * @param processors   cores each run's JVM sees
     * @param sandbox      true to make each run in the sandbox
     * @param trusted      true to run the submissions trusted (tests only: a hole opened on purpose)
     */
    record Limits(int heapMb, double wallSeconds, double hangSeconds, Double seconds, long sampleMillis, int processors,
            boolean sandbox, boolean trusted) {
    }

    /**
     * What came back.
     *
     * @param record      the run as the report holds it
     * @param wallSeconds real time it took, s
     * @param trace       the replay's trace, or null when there is none
     * @param log         the run's command log as received, or null
     * @param page        what the run's page says besides the replay (null without a replay)
     * @param tape        the replay's samples for the page (null without a replay)
     * @param diverged    what differed from the replay, from a JVM that ended normally: the run is made again once
     *                    ({@link Rerun}); null when nothing did
     */
    record Outcome(RunRecord record, double wallSeconds, Path trace, Path log, RunOutcome page, RunPageRecorder tape,
            String diverged) {
        Outcome(RunRecord record, double wallSeconds, Path trace, Path log, RunOutcome page, RunPageRecorder tape) {
            this(record, wallSeconds, trace, log, page, tape, null);
        }
    }

    private ChildRun() {
    }

    /**
     * @param job     the run
     * @param sub     the student's submission (runnable)
     * @param arena   the arena
     * @param lim     the limits
     * @param runs    where the run's trace and log go
     * @param sockets a folder of the grader's own for the channel's socket
     * @param slot    which of the concurrent runs this is, from 0
     * @param running the children going now (a signal to the grader kills them)
     * @return what came back
     * @throws IOException if the child cannot be started
     */
    static Outcome run(GradePlan.Job job, Submission sub, Arena arena, Limits lim, Path runs, Path sockets, int slot,
            Set<Process> running) throws IOException {
        Path trace = runs.resolve(ReportFiles.runId(job) + ".trace");
        Path logFile = runs.resolve(ReportFiles.runId(job) + ".log.gz");
        Files.deleteIfExists(trace);
        Files.deleteIfExists(logFile);
        Path socket = sockets.resolve(job.index() + ".sock");
        List<String> java = new ArrayList<>(jvmOptions(lim));
        java.add(GradedRun.MAIN);
        java.addAll(runArgs(job, sub, lim, lim.sandbox() ? Box.CHANNEL : socket));
        long start = System.nanoTime();
        boolean killed = false;
        int exit;
        String err;
        boolean cut;
        try (LogChannel.Receiver receiver = new LogChannel.Receiver(socket, logFile, Verdict.MAX_LOG_BYTES)) {
            List<String> cmd;
            if (lim.sandbox()) {
                cmd = Box.command(new Box.Spec(boxed(sub, List.of(job.arena())), List.of(), socket, false,
                        BoxLimits.forRun(lim.heapMb(), arena.robots().size(), lim.wallSeconds()), slot), java);
            } else {
                cmd = unboxed(java);
            }
            // Standard input stays a pipe the grader never writes to: the child ends when it ends (the grader is gone).
            Process p = new ProcessBuilder(cmd).start();
            running.add(p);
            try {
                Tail out = new Tail(p.getInputStream(), 64 << 10, "grade-out-" + job.index());
                Tail errTail = new Tail(p.getErrorStream(), 64 << 10, "grade-err-" + job.index());
                try {
                    if (!p.waitFor((long) (lim.wallSeconds() * 1000), TimeUnit.MILLISECONDS)) {
                        killed = true;
                        kill(p);
                    }
                } catch (InterruptedException e) {
                    kill(p);
                    Thread.currentThread().interrupt();
                    throw new IOException("grading was interrupted", e);
                }
                exit = p.exitValue();
                p.getOutputStream().close();
                receiver.awaitEnd(10_000);
                cut = receiver.overLimit();
                out.text(2000); // drained: standard output is no result of anything
                err = strip(errTail.text(5000), sub);
            } finally {
                running.remove(p);
            }
        }
        double wall = (System.nanoTime() - start) / 1e9;
        String madeIn = lim.sandbox() ? RunRecord.SANDBOX : RunRecord.NO_SANDBOX;
        Verdict.Child child =
                new Verdict.Child(killed, exit, err, Files.isRegularFile(logFile) ? logFile : null, cut, madeIn);
        Verdict.Judged judged = Verdict.judge(job, sub, arena, lim, child, trace);
        return new Outcome(judged.record(), wall, Files.isRegularFile(trace) ? trace : null, child.log(), judged.page(),
                judged.tape(), judged.diverged());
    }

    /**
     * @param lim the limits
     * @return the options of a graded JVM (a run's own, or a warm worker's): heap, collector, cores, the
     *     simulator's classpath at its real location; its main class ({@link GradedRun}, {@link WorkerMain}) comes next
     */
    static List<String> jvmOptions(Limits lim) {
        return jvmOptions(lim, ClassArchive.current());
    }

    /**
     * @param lim     the limits
     * @param archive the jar's class-data archive, if it has one that fits (docs/startup.md)
     * @return {@link #jvmOptions(Limits)} with this archive
     */
    static List<String> jvmOptions(Limits lim, Optional<Path> archive) {
        // Native access for JNA (the controller threads' core, see host.CpuAffinity): Java 22+ warns without it.
        List<String> java = new ArrayList<>(List.of("--enable-native-access=ALL-UNNAMED", "-Xmx" + lim.heapMb() + "m",
                "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1",
                "-XX:ActiveProcessorCount=" + lim.processors(), "-Djava.awt.headless=true"));
        archive.ifPresent(a -> java.addAll(ClassArchive.jvmOptions(a)));
        java.addAll(List.of("-cp", OwnClasspath.asOption()));
        return List.copyOf(java);
    }

    /**
     * @param job     the run
     * @param sub     the submission
     * @param lim     the limits
     * @param channel the run's command-log socket as the run sees it
     * @return a graded run's arguments ({@link GradedRun.Args})
     */
    static List<String> runArgs(GradePlan.Job job, Submission sub, Limits lim, Path channel) {
        Path arenaFile = arenaFile(job.arena());
        return new GradedRun.Args(arenaFile != null ? arenaFile.toString() : job.arena(), sub.classpath(),
                sub.controller(),
                job.seed(), lim.hangSeconds(), lim.sampleMillis(), channel, lim.wallSeconds(),
                lim.seconds(), lim.trusted())
                .toList();
    }

    /** @return the arena as a file (absolute), or null for a bundled arena */
    private static Path arenaFile(String arena) {
        return Files.isRegularFile(Path.of(arena)) ? Path.of(arena).toAbsolutePath() : null;
    }

    /**
     * @param sub    the submission
     * @param arenas the arenas its runs use
     * @return what a box of its runs shows, read-only: the simulator, the submission's classes, the arena files
     */
    static List<Path> boxed(Submission sub, List<String> arenas) {
        return boxed(sub, arenas, ClassArchive.current());
    }

    /**
     * @param sub     the submission
     * @param arenas  the arenas its runs use
     * @param archive the jar's class-data archive, if it has one that fits
     * @return {@link #boxed(Submission, List)}, the archive too (beside the jar, at its real path)
     */
    static List<Path> boxed(Submission sub, List<String> arenas, Optional<Path> archive) {
        List<Path> read = new ArrayList<>(OwnClasspath.entries());
        archive.ifPresent(read::add);
        read.add(sub.classpath().toAbsolutePath());
        for (String a : arenas) {
            Path f = arenaFile(a);
            if (f != null && !read.contains(f)) {
                read.add(f);
            }
        }
        return read;
    }

    /** @return the command that starts this JVM outside a box */
    static List<String> unboxed(List<String> java) {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(java);
        return cmd;
    }

    /** Kill a child and everything it started (bubblewrap's own child dies with it too). */
    static void kill(Process p) {
        p.descendants().forEach(ProcessHandle::destroyForcibly);
        p.destroyForcibly();
        try {
            p.waitFor(30, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    static String format(double d) {
        return String.format(Locale.ROOT, "%s", d == StrictMath.rint(d) ? Long.toString((long) d) : Double.toString(d));
    }

    /**
     * The submission's class folder lies under --out: its files are named from there on, so that the
     * report does not depend on where it was written (shards merge byte for byte into it).
     */
    static String strip(String text, Submission sub) {
        String classes = sub.classpath().toAbsolutePath().normalize() + File.separator;
        String absolute = sub.classpath().toAbsolutePath() + File.separator;
        String given = sub.classpath() + File.separator;
        for (String p : new String[] {classes, absolute, given}) {
            text = text.replace(p, "");
        }
        return text;
    }
}
