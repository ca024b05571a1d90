package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.files.AtomicFiles;

/**
 * Grades a folder of submissions (or one shard of the grading): compiles them, makes each run in a
 * child JVM, {@code jobs} at a time, draws each run's trajectory and writes the report.
 */
public final class Grader {

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
     * @param keepTraces   keep each run's trace under {@code runs/} (else deleted once drawn)
     * @param progress     where the progress goes
     * @param terminal     true to redraw a bar in place, false for a line per run
     */
    public record Options(Path submissions, List<String> arenas, int seeds, int jobs, Path out, GradePlan.Shard shard,
            int heapMb, double wallSeconds, double hangSeconds, Double seconds, boolean keepTraces, PrintStream progress,
            boolean terminal) {
    }

    private Grader() {
    }

    /**
     * @param o the options
     * @return the report written to {@code o.out()}
     * @throws IllegalArgumentException for a missing folder or a bad arena, naming the fix
     */
    public static ReportFiles.Report grade(Options o) {
        if (o.jobs() < 1) {
            throw new IllegalArgumentException("--jobs " + o.jobs() + ": give at least 1");
        }
        List<Path> folders = Submissions.folders(o.submissions());
        GradePlan plan = new GradePlan(folders.stream().map(p -> p.getFileName().toString()).toList(), o.arenas(), o.seeds());
        Map<String, Arena> arenas = new HashMap<>();
        for (String a : o.arenas()) {
            arenas.put(a, ArenaFormat.resolve(a));
        }
        List<GradePlan.Job> jobs = plan.shard(o.shard());
        Path work = o.out().resolve("work");
        Map<String, Submission> subs = new LinkedHashMap<>();
        for (Path f : folders) {
            String student = f.getFileName().toString();
            if (jobs.stream().anyMatch(j -> j.student().equals(student))) {
                subs.put(student, Submissions.prepare(f, work.resolve(student)));
            }
        }
        int processors = StrictMath.max(1, Runtime.getRuntime().availableProcessors() / o.jobs());
        ChildRun.Limits limits = new ChildRun.Limits(o.heapMb(), o.wallSeconds(), o.hangSeconds(), o.seconds(), 250,
                processors);
        try {
            Files.createDirectories(work.resolve("runs"));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot make " + work + ": " + e.getMessage(), e);
        }
        Progress progress = new Progress(o.progress(), jobs.size(), o.terminal());
        ExecutorService pool = Executors.newFixedThreadPool(o.jobs());
        List<Future<ChildRun.Outcome>> futures = new ArrayList<>();
        for (GradePlan.Job job : jobs) {
            futures.add(pool.submit(() -> {
                ChildRun.Outcome outcome = one(job, subs.get(job.student()), limits, arenas.get(job.arena()), o, work);
                progress.finished(job, outcome.record());
                return outcome;
            }));
        }
        List<RunRecord> records = new ArrayList<>();
        StringBuilder timings = new StringBuilder("run,status,wall_s\n");
        try {
            for (int i = 0; i < jobs.size(); i++) {
                ChildRun.Outcome outcome = futures.get(i).get();
                records.add(outcome.record());
                timings.append(ReportFiles.runId(jobs.get(i))).append(',').append(outcome.record().status().word())
                        .append(',').append(String.format(Locale.ROOT, "%.3f", outcome.wallSeconds())).append('\n');
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("grading was interrupted", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("a run could not be made: " + e.getCause(), e.getCause());
        } finally {
            pool.shutdownNow();
        }
        ReportFiles.Report report = new ReportFiles.Report(plan, o.shard(), records);
        ReportFiles.write(report, o.out());
        try {
            AtomicFiles.write(o.out().resolve("timings.csv"), timings.toString());
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write timings.csv: " + e.getMessage(), e);
        }
        return report;
    }

    private static ChildRun.Outcome one(GradePlan.Job job, Submission sub, ChildRun.Limits limits, Arena arena, Options o,
            Path work) throws IOException {
        if (!sub.runnable()) {
            RunRecord r = new RunRecord(job.student(), job.arena(), job.seed(), RunStatus.COMPILE_FAILED, 0,
                    arena.assignment().maxPoints(), 0, 0, sub.controller(), sub.problem(), "");
            return new ChildRun.Outcome(r, 0, null);
        }
        ChildRun.Outcome outcome = ChildRun.run(job, sub, limits, work.resolve("runs"));
        RunRecord r = outcome.record();
        if (r.max() == 0 && arena.assignment().hasTasks()) {
            r = new RunRecord(r.student(), r.arena(), r.seed(), r.status(), 0, arena.assignment().maxPoints(), 0,
                    r.simulatedSeconds(), r.controller(), r.detail(), "");
        }
        if (outcome.trace() != null) {
            String picture = "img/" + ReportFiles.runId(job) + ".png";
            try {
                TrajectoryPicture.draw(arena, outcome.trace(), o.out().resolve(picture), 320);
                r = new RunRecord(r.student(), r.arena(), r.seed(), r.status(), r.points(), r.max(), r.percent(),
                        r.simulatedSeconds(), r.controller(), r.detail(), picture);
            } finally {
                if (!o.keepTraces()) {
                    Files.deleteIfExists(outcome.trace());
                }
            }
        }
        return new ChildRun.Outcome(r, outcome.wallSeconds(), outcome.trace());
    }
}
