package org.kheperasim.sim.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.kheperasim.link.tool.CliNumbers;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.link.tool.ToolErrors;
import org.kheperasim.sim.grade.CommonFailure;
import org.kheperasim.sim.grade.GradePlan;
import org.kheperasim.sim.grade.Grader;
import org.kheperasim.sim.grade.ReportFiles;
import org.kheperasim.sim.grade.ReportMerge;
import org.kheperasim.sim.text.Shown;
import org.kheperasim.sim.grade.platform.JunitCommand;
import org.kheperasim.sim.grade.platform.PlatformOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code grade}: every submission in every arena with every seed, on warm worker JVMs (one per submission); a report.
 */
@Command(name = "grade", mixinStandardHelpOptions = true, sortOptions = false,
        subcommands = {GradeCommand.Merge.class, JunitCommand.class},
        description = {"Grade a class: compile every submission (one sub-folder per student, .java or"
                + " .class), run it in every arena with seeds 1..N, each submission's runs one after another in a"
                + " worker JVM of its own (each run with fresh class loaders, the same result as in a JVM of its own, a"
                + " heap, simulated-time and wall-clock limit; --worker-runs 1: each run in a JVM of its own) under the"
                + " containment rules, in an operating-system sandbox (bubblewrap), scored by the grader's own replay"
                + " of the run's command log, and write a report (report.txt, results.csv, results.json, index.html"
                + " with trajectory pictures) ranked per arena by the arenas' tasks. Started again on the"
                + " same --out, it makes only the runs its journal lacks. See docs/grading.md.",
            "--shard K/N makes one deterministic slice; 'grade merge' joins the slices into the same report."})
final class GradeCommand implements Callable<Integer> {

    @Option(names = "--submissions", paramLabel = "DIR",
            description = "the folder with one sub-folder per student (required)")
    Path submissions;

    @Option(names = "--arenas", arity = "1..*", paramLabel = "ARENA",
            description = "arena files or bundled arenas (${COMPLETION-CANDIDATES}) (required)",
            completionCandidates = BundledArenas.class)
    List<String> arenas = new ArrayList<>();

    @Option(names = "--seeds", paramLabel = "N", defaultValue = "5", converter = CliNumbers.PositiveInt.class,
            description = "run seeds 1..N (default: ${DEFAULT-VALUE})")
    int seeds;

    @Option(names = "--jobs", paramLabel = "K", defaultValue = "1", converter = CliNumbers.PositiveInt.class,
            description = "runs at once, each in a worker JVM of its own (default: ${DEFAULT-VALUE}; about 1 per core)")
    int jobs;

    @Option(names = "--out", paramLabel = "DIR", defaultValue = "grade-report",
            description = "the report folder (default: ${DEFAULT-VALUE})")
    Path out;

    @Option(names = "--shard", paramLabel = "K/N",
            description = "make only shard K of N (1 <= K <= N); join with 'grade merge'")
    String shard;

    @Option(names = "--seconds", paramLabel = "T", converter = CliNumbers.PositiveSeconds.class,
            description = "simulated seconds per run (default: each arena's time-limit, else 600)")
    Double seconds;

    @Option(names = "--heap-mb", paramLabel = "MB", defaultValue = "256",
            description = "each run's heap limit, MiB (default: ${DEFAULT-VALUE})")
    int heapMb;

    @Option(names = "--wall-limit", paramLabel = "SECONDS", defaultValue = "300",
            converter = CliNumbers.PositiveSeconds.class,
            description = "real seconds a run may take before it is killed and counted as hung (default:"
                    + " ${DEFAULT-VALUE})")
    double wallLimit;

    @Option(names = "--hang-timeout", paramLabel = "SECONDS", defaultValue = "5",
            converter = CliNumbers.PositiveSeconds.class,
            description = "real seconds without an API call after which a controller counts as hung (default:"
                    + " ${DEFAULT-VALUE})")
    double hangTimeout;

    @Option(names = "--keep-traces",
            description = "keep each run's trace and command log in DIR/work/runs (they are deleted once drawn)")
    boolean keepTraces;

    @Option(names = "--no-sandbox",
            description = "make the runs without the operating-system sandbox (bubblewrap): only for"
            + " code you trust; needed where there is none (macOS, Windows, no user namespaces). The report"
            + " says which way each run was made")
    boolean noSandbox;

    @Option(names = "--worker-runs", paramLabel = "N", converter = CliNumbers.PositiveInt.class,
            description = "the most runs one worker JVM makes, one after another, each with fresh class"
                    + " loaders (default: all of a submission's runs); 1 makes every run in a JVM of its own, as"
                    + " before workers")
    Integer workerRuns;

    @Mixin
    PlatformOptions platforms;

    @Override
    public Integer call() {
        // Not picocli-required: 'grade merge' must not need them.
        if (submissions == null || arenas.isEmpty()) {
            throw new IllegalArgumentException(
                    "grade needs --submissions DIR and --arenas ARENA...; e.g. grade --submissions"
                    + " hand-ins --arenas maze two-rooms --seeds 5 (or 'grade merge --out DIR SHARD_DIR...')");
        }
        if (heapMb < 32) {
            throw new IllegalArgumentException("--heap-mb " + heapMb + ": give at least 32 (MiB)");
        }
        GradePlan.Shard s = shard == null ? GradePlan.Shard.ALL : GradePlan.Shard.parse(shard);
        platforms.formats();
        platforms.check(arenas);
        long t0 = System.nanoTime();
        ReportFiles.Report report =
                Grader.grade(new Grader.Options(submissions, arenas, seeds, jobs, out, s, heapMb, wallLimit,
                hangTimeout, seconds, keepTraces, System.err, System.console() != null, !noSandbox, false,
                workerRuns == null ? Integer.MAX_VALUE : workerRuns, platforms.deadlineSeconds()));
        platforms.write(report, out, StrictMath.round((System.nanoTime() - t0) / 1e9));
        print(report, out);
        return failedAlike(report);
    }

    /** A grading whose every run failed for one reason says so last, on standard error, and exits 1. */
    static int failedAlike(ReportFiles.Report report) {
        return CommonFailure.of(report.runs()).map(line -> {
            System.err.println(ToolErrors.prefix("khepera-sim") + Shown.visible(line));
            System.err.flush();
            return ExitCodes.FAILED;
        }).orElse(ExitCodes.OK);
    }

    static void print(ReportFiles.Report report, Path out) {
        try {
            System.out.print(java.nio.file.Files.readString(out.resolve("report.txt")));
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        System.out.println("Report: " + out.resolve("index.html") + " (also results.csv, results.json)"
                + (report.shard().n() > 1 ? "; shard " + report.shard() + ": join the shards with grade merge" : ""));
    }

    /** {@code grade merge}: join the shards' reports. */
    @Command(name = "merge", mixinStandardHelpOptions = true,
            description = "Join the report folders of 'grade --shard K/N' runs (all N of them) into one"
                    + " report, the same as one unsharded grading writes.")
    static final class Merge implements Callable<Integer> {
        @Option(names = "--out", paramLabel = "DIR", defaultValue = "grade-report",
                description = "the merged report's folder (default: ${DEFAULT-VALUE})")
        Path out;

        @Parameters(arity = "1..*", paramLabel = "SHARD_DIR", description = "the shards' report folders")
        List<Path> shards = new ArrayList<>();

        @Override
        public Integer call() {
            ReportFiles.Report report = ReportMerge.merge(shards, out);
            print(report, out);
            return failedAlike(report);
        }
    }
}
