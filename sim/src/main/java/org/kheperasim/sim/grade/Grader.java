package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.stream.Stream;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.files.AtomicFiles;
import org.kheperasim.sim.sandbox.BoxProbe;
import org.kheperasim.sim.web.RunPage;

/**
 * Grades a folder of submissions (or one shard of the grading): compiles them, makes each run in a
 * child JVM, {@code jobs} at a time, in the operating-system sandbox unless told otherwise, judges
 * each by the replay of its command log ({@link Verdict}), draws its trajectory and writes the report.
 * Each finished run goes to the journal at once ({@link Journal}): a grading started again on the same
 * folder makes only the runs it lacks and writes the same report. A signal to the grader (SIGTERM,
 * Ctrl-C) kills the runs going; after {@code kill -9} they end by themselves (see {@link ChildSide}).
 */
public final class Grader {
    /** The first line of {@code timings.csv}: per run its child's wall seconds and its page's. */
    static final String TIMINGS_HEADER = "run,status,wall_s,page_s\n";
    /**
     * The replay's trace's sample period, ms, enough for the picture (the page takes the replay's
     * snapshots every 50 ms itself, see {@link Verdict}).
     */
    static final long SAMPLE_MILLIS = 250;
    /** The folder of the runs' web pages, in the report folder. */
    static final String PAGES = "pages/";

    /**
     * What to grade and how.
     *
     * @param submissions  the folder with one sub-folder per student
     * @param arenas       bundled arena names or arena files
     * @param seeds        seeds 1..seeds
     * @param jobs         runs at once, ≥ 1
     * @param out          the report folder
     * @param shard        the slice to make
     * @param heapMb       each run's heap limit, MiB
     * @param wallSeconds  each run's wall-clock limit, s
     * @param hangSeconds  real seconds without an API call after which a controller counts as hung
     * @param seconds      simulated seconds per run, or null for each arena's time-limit (600 s without one)
     * @param keepTraces   keep each run's trace and command log under {@code work/runs/} (else deleted once drawn)
     * @param progress     where the progress goes
     * @param terminal     true to redraw a bar in place, false for a line per run
     * @param sandbox      true to make each run in the operating-system sandbox (refused where there is none)
     * @param trustedForTests true to run the submissions trusted, uncontained in their JVM: only for tests of
     *                     the sandbox and of the score's checks, which need a controller that escapes; no
     *                     command-line option sets it
     * @param workerRuns   the most runs one worker JVM makes ({@link WorkerSlots}); 1 makes every run in a JVM of its
     *                     own, as before workers ({@link ChildRun}); {@link Integer#MAX_VALUE}: all of a submission's
     * @param deadline     the grading's own deadline, real seconds from its start ({@link GradeDeadline}), or null for
     *     none
     */
    public record Options(Path submissions, List<String> arenas, int seeds, int jobs, Path out, GradePlan.Shard shard,
            int heapMb, double wallSeconds, double hangSeconds, Double seconds, boolean keepTraces,
            PrintStream progress,
            boolean terminal, boolean sandbox, boolean trustedForTests, int workerRuns, Double deadline) {
        /** Without a deadline of the grading's own. */
        public Options(Path submissions, List<String> arenas, int seeds, int jobs, Path out, GradePlan.Shard shard,
                int heapMb, double wallSeconds, double hangSeconds, Double seconds, boolean keepTraces,
                PrintStream progress,
                boolean terminal, boolean sandbox, boolean trustedForTests, int workerRuns) {
            this(submissions, arenas, seeds, jobs, out, shard, heapMb, wallSeconds, hangSeconds, seconds,
                    keepTraces, progress,
                    terminal, sandbox, trustedForTests, workerRuns, null);
        }

        /** Runs on warm workers, each making all of its submission's runs. */
        public Options(Path submissions, List<String> arenas, int seeds, int jobs, Path out, GradePlan.Shard shard,
                int heapMb, double wallSeconds, double hangSeconds, Double seconds, boolean keepTraces,
                PrintStream progress,
                boolean terminal, boolean sandbox, boolean trustedForTests) {
            this(submissions, arenas, seeds, jobs, out, shard, heapMb, wallSeconds, hangSeconds, seconds,
                    keepTraces, progress,
                    terminal, sandbox, trustedForTests, Integer.MAX_VALUE);
        }
    }

    private Grader() {
    }

    /**
     * @param o the options
     * @return the report written to {@code o.out()}
     * @throws IllegalArgumentException for a missing folder, a bad arena, or no sandbox where one is asked for, naming
     *     the fix
     */
    public static ReportFiles.Report grade(Options o) {
        long endNanos = o.deadline() == null ? Long.MAX_VALUE : System.nanoTime() + (long) (o.deadline() * 1e9);
        if (o.jobs() < 1) {
            throw new IllegalArgumentException("--jobs " + o.jobs() + ": give at least 1");
        }
        if (o.workerRuns() < 1) {
            throw new IllegalArgumentException("--worker-runs " + o.workerRuns()
                    + ": give at least 1 (1: every run in a JVM"
                    + " of its own)");
        }
        List<Path> folders = Submissions.folders(o.submissions());
        GradePlan plan = new GradePlan(folders.stream().map(p -> p.getFileName().toString()).toList(),
                o.arenas(), o.seeds());
        Map<String, Arena> arenas = new HashMap<>();
        for (String a : o.arenas()) {
            arenas.put(a, ArenaFormat.resolve(a));
        }
        if (o.sandbox()) {
            BoxProbe.unavailable().ifPresent(reason -> {
                throw new IllegalArgumentException(BoxProbe.refusal("grade", reason));
            });
        }
        List<GradePlan.Job> jobs = plan.shard(o.shard());
        Path work = o.out().resolve("work");
        try (Journal journal = Journal.open(o.out(), Journal.identity(plan, o.shard(), String.format(Locale.ROOT,
                "seconds=%s; hang=%s; heap=%d", o.seconds(), o.hangSeconds(), o.heapMb())))) {
            List<GradePlan.Job> todo = jobs.stream().filter(j -> !done(journal, j, o.out())).toList();
            if (!todo.isEmpty()) {
                makeRuns(o, todo, jobs.size() - todo.size(), jobs.size(), folders, arenas, work, journal, endNanos);
            }
            List<RunRecord> records = new ArrayList<>();
            StringBuilder timings = new StringBuilder(TIMINGS_HEADER);
            for (int i = 0; i < jobs.size(); i++) {
                Journal.Entry e = journal.done().get(jobs.get(i).index());
                if (e == null) { // only past the grading's deadline
                    if (o.deadline() == null) {
                        throw new IllegalStateException("run " + ReportFiles.runId(jobs.get(i))
                                + " was not made (the grading"
                                + " was stopped); grade again on the same --out to make it");
                    }
                    records.add(GradeDeadline.notMade(jobs.get(i), arenas.get(jobs.get(i).arena()), o.deadline()));
                    continue;
                }
                records.add(e.record());
                timings.append(ReportFiles.runId(jobs.get(i))).append(',')
                        .append(e.record().status().word()).append(',')
                        .append(String.format(Locale.ROOT, "%.3f,%.3f", e.wallSeconds(), e.pageSeconds())).append('\n');
            }
            ReportFiles.Report report = new ReportFiles.Report(plan, o.shard(), records);
            ReportFiles.write(report, o.out());
            AtomicFiles.write(o.out().resolve("timings.csv"), timings.toString());
            return report;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write timings.csv: " + e.getMessage(), e);
        }
    }

    /** A run the journal holds counts as made, unless its picture or its page has gone since. */
    private static boolean done(Journal journal, GradePlan.Job job, Path out) {
        Journal.Entry e = journal.done().get(job.index());
        return e != null && (e.record().picture().isEmpty() || Files.isRegularFile(out.resolve(e.record().picture())))
                && (e.record().page().isEmpty() || Files.isRegularFile(out.resolve(e.record().page())));
    }

    private static void makeRuns(Options o, List<GradePlan.Job> todo, int alreadyDone, int total,
            List<Path> folders,
            Map<String, Arena> arenas, Path work, Journal journal, long endNanos) {
        int processors = StrictMath.max(1, Runtime.getRuntime().availableProcessors() / o.jobs());
        ChildRun.Limits limits =
                new ChildRun.Limits(o.heapMb(), o.wallSeconds(), o.hangSeconds(), o.seconds(), SAMPLE_MILLIS,
                processors, o.sandbox(), o.trustedForTests());
        Path sockets;
        try {
            Files.createDirectories(work.resolve("runs"));
            sockets = privateFolder();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot make " + work + ": " + e.getMessage(), e);
        }
        Set<Process> running = ConcurrentHashMap.newKeySet();
        // A signal to the grader (SIGTERM, Ctrl-C): no run outlives it. What finished is in the journal; a run the
        // grader's own stop killed is no result of the student's and goes to no journal (a resumed grading makes it).
        AtomicBoolean stopping = new AtomicBoolean();
        Thread killRuns = new Thread(() -> {
            stopping.set(true);
            running.forEach(ChildRun::kill);
        }, "grade-stop-runs");
        Runtime.getRuntime().addShutdownHook(killRuns);
        AtomicBoolean allBack = new AtomicBoolean();
        AtomicBoolean deadlinePassed = new AtomicBoolean();
        if (endNanos != Long.MAX_VALUE) {
            GradeDeadline.watch(endNanos, stopping, deadlinePassed, allBack, running);
        }
        Progress progress = new Progress(o.progress(), total, o.terminal());
        progress.skip(alreadyDone);
        Compiling[] prepared = new Compiling[1];
        // A run that came back before a stop is journaled even when its judgement ends after it.
        WorkerSlots.Finisher finisher = (job, outcome, cameBack) -> {
            if (!cameBack) {
                return;
            }
            Made made = one(job, prepared[0].get(job.student()), arenas.get(job.arena()), o, outcome);
            journal.add(job, new Journal.Entry(made.outcome().record(), made.outcome().wallSeconds(),
                    made.pageSeconds()));
            progress.finished(job, made.outcome().record());
        };
        Set<String> students = new HashSet<>();
        todo.forEach(j -> students.add(j.student()));
        // Prepared while the first runs go; a submission that cannot run needs no JVM: its records are written
        // as soon as it is prepared (even past the deadline: they need no run).
        try (Compiling subs = new Compiling(folders, students, work, stopping, sub -> {
            if (!sub.runnable()) {
                for (GradePlan.Job job : todo) {
                    if (job.student().equals(sub.student())) {
                        Made made = one(job, sub, arenas.get(job.arena()), o, null);
                        journal.add(job, new Journal.Entry(made.outcome().record(), 0, 0));
                        progress.finished(job, made.outcome().record());
                    }
                }
            }
        })) {
            prepared[0] = subs;
            if (o.workerRuns() == 1) {
                eachInItsOwnJvm(o, todo, subs, arenas, limits, work, sockets, running, finisher, stopping);
            } else {
                WorkerSlots.Summary made = WorkerSlots.makeAll(todo, subs, arenas, limits, o.jobs(), o.workerRuns(),
                        work.resolve("runs"), sockets, running, finisher, stopping);
                o.progress().println(made.line());
            }
            subs.awaitAll();
        } finally {
            allBack.set(true);
            if (deadlinePassed.get()) {
                o.progress().println("the grading's deadline (--deadline " + GradeDeadline.shown(o.deadline())
                        + ") passed: the"
                        + " runs going were stopped; the report holds the runs made before it");
            }
            running.forEach(ChildRun::kill);
            try {
                Runtime.getRuntime().removeShutdownHook(killRuns);
            } catch (IllegalStateException shuttingDown) {
                // the hook is killing the runs
            }
            deleteTree(sockets);
        }
    }

    /** Each run in a child JVM of its own ({@code --worker-runs 1}): {@code jobs} at a time. */
    private static void eachInItsOwnJvm(Options o, List<GradePlan.Job> todo, Compiling subs,
            Map<String, Arena> arenas, ChildRun.Limits limits, Path work, Path sockets, Set<Process> running,
            WorkerSlots.Finisher finisher, AtomicBoolean stopping) {
        BlockingQueue<Integer> slots = new ArrayBlockingQueue<>(o.jobs());
        for (int i = 0; i < o.jobs(); i++) {
            slots.add(i);
        }
        ExecutorService pool = Executors.newFixedThreadPool(o.jobs());
        List<Future<?>> futures = new ArrayList<>();
        for (GradePlan.Job job : todo) {
            futures.add(pool.submit(() -> {
                int slot = slots.take();
                try {
                    if (stopping.get()) {
                        return null;
                    }
                    Submission sub = subs.get(job.student());
                    if (sub != null && sub.runnable()) { // else its records were written as it was prepared
                        // A result that differed from its replay is made again once, in a JVM of its own too.
                        Rerun.Making making =
                                () -> ChildRun.run(job, sub, arenas.get(job.arena()), limits, work.resolve("runs"),
                                sockets, slot, running);
                        ChildRun.Outcome made = Rerun.guard(making.make(), making);
                        finisher.finish(job, made, !stopping.get());
                    }
                } finally {
                    slots.add(slot);
                }
                return null;
            }));
        }
        awaitAll(pool, futures);
    }

    /** Wait for every job of {@code pool}, then shut it down; a job's failure is the grading's. */
    static void awaitAll(ExecutorService pool, List<Future<?>> futures) {
        try {
            for (Future<?> f : futures) {
                f.get();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("grading was interrupted", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("a run could not be made: " + e.getCause(), e.getCause());
        } finally {
            pool.shutdownNow();
        }
    }

    /** A run made, and the real time its page took, s. */
    private record Made(ChildRun.Outcome outcome, double pageSeconds) {
    }

    /**
     * A run's record, picture and page, from what came back of it (null for a submission that cannot run),
     * however it was made.
     */
    private static Made one(GradePlan.Job job, Submission sub, Arena arena, Options o, ChildRun.Outcome outcome)
            throws IOException {
        if (!sub.runnable()) {
            RunRecord r = new RunRecord(job.student(), job.arena(), job.seed(),
                    sub.empty() ? RunStatus.NOTHING_HANDED_IN : RunStatus.COMPILE_FAILED, 0,
                    arena.assignment().maxPoints(), 0, 0, sub.controller(), sub.problem(), "", "");
            return new Made(new ChildRun.Outcome(r, 0, null, null, null, null), 0);
        }
        RunRecord r = outcome.record();
        if (r.max() == 0 && arena.assignment().hasTasks()) {
            r = new RunRecord(r.student(), r.arena(), r.seed(), r.status(), 0, arena.assignment().maxPoints(), 0,
                    r.simulatedSeconds(), r.controller(), r.detail(), "", r.madeIn()).withRerun(r.rerun());
        }
        double pageSeconds = 0;
        try {
            if (outcome.trace() != null) {
                // The picture and the page are made from the grader's own replay, never from anything the run wrote.
                String picture = "img/" + ReportFiles.runId(job) + ".png";
                TrajectoryPicture.draw(arena, outcome.trace(), o.out().resolve(picture), 320);
                r = r.withPicture(picture);
                if (outcome.page() != null && outcome.tape() != null) {
                    long t0 = System.nanoTime();
                    r = withPage(r, job, outcome, o);
                    pageSeconds = (System.nanoTime() - t0) / 1e9;
                }
            }
        } finally {
            if (!o.keepTraces()) {
                for (Path p : new Path[] {outcome.trace(), outcome.log(),
                        outcome.log() == null ? null : Rerun.firstLog(outcome.log())}) {
                    if (p != null) {
                        Files.deleteIfExists(p);
                    }
                }
            }
        }
        return new Made(new ChildRun.Outcome(r, outcome.wallSeconds(), outcome.trace(), outcome.log(), null, null),
                pageSeconds);
    }

    /**
     * The run's page, from the grader's replay; a page that cannot be made (a replay without a sample)
     * costs the run its page, said on the progress stream, never the grading.
     */
    private static RunRecord withPage(RunRecord r, GradePlan.Job job, ChildRun.Outcome outcome, Options o)
            throws IOException {
        String page = PAGES + ReportFiles.runId(job) + ".html";
        Files.createDirectories(o.out().resolve(PAGES));
        try {
            RunPage.write(outcome.tape(), outcome.page(), "the grader's replay of the run's command log",
                    o.out().resolve(page));
            return r.withPage(page);
        } catch (IllegalArgumentException | IllegalStateException | UncheckedIOException e) {
            o.progress().println("note: " + ReportFiles.runId(job) + " has no web page: " + e.getMessage());
            return r;
        }
    }

    /** A folder only the grader's user may enter: the runs' sockets live there (a box sees only its own). */
    private static Path privateFolder() throws IOException {
        try {
            return Files.createTempDirectory("khepera-grade-", PosixFilePermissions.asFileAttribute(
                    PosixFilePermissions.fromString("rwx------")));
        } catch (UnsupportedOperationException e) {
            return Files.createTempDirectory("khepera-grade-");
        }
    }

    private static void deleteTree(Path folder) {
        try (Stream<Path> s = Files.walk(folder)) {
            for (Path p : s.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        } catch (IOException e) {
            // a temporary folder left behind
        }
    }
}
