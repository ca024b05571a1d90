package org.kheperasim.sim.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicInteger;
import org.kheperasim.link.tool.CliNumbers;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.link.tool.ToolErrors;
import org.kheperasim.sim.eval.Evaluator;
import org.kheperasim.sim.eval.Job;
import org.kheperasim.sim.eval.Outcome;
import org.kheperasim.sim.files.BoundedLines;
import org.kheperasim.sim.files.InputFileException;
import org.kheperasim.sim.grade.GradePlan;
import org.kheperasim.sim.text.Shown;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code evaluate}: many runs in one warm JVM on every core; JSON lines in, one JSON line per finished job out. */
@Command(name = "evaluate", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Evaluate many runs of your own controllers in one JVM on all cores: a job per line of JSON in"
                + " (--jobs FILE, or standard input), one line of JSON per finished job out (standard"
                + " output, or --out), for a parameter sweep or an evolutionary algorithm in any language driving it"
                + " through a pipe.",
            "A job: {\"id\": \"g3-17\", \"controller\": \"StepBraitenberg\", \"arena\": \"maze-easy\", \"seed\": 5,"
                + " \"seconds\": 60, \"parameters\": {\"weights\": [0.4, 0.8], \"gain\": 2}, \"settings\":"
                + " {\"noise.reading\": \"0.5\"}, \"trace\": \"runs/g3-17.trace\"}; only controller and"
                + " arena are needed (or --controller, --arena); seed defaults to the job's line number, seconds"
                + " to --seconds.",
            "Each outcome names its job's index (its line, from 0) and id, and is the same for any --threads and any"
                + " order of completion. The controllers run as your own code (unchecked); code not your own is graded"
                + " with 'grade', in a sandbox. See docs/evaluate.md."})
final class EvaluateCommand implements Callable<Integer> {
    /** The longest job line, characters: a job with thousands of parameters is a few hundred KB. */
    static final int MAX_JOB_CHARS = 1 << 20;

    @Option(names = "--jobs", paramLabel = "FILE", defaultValue = "-", description = "the jobs, a JSON object per line"
            + " (- for standard input, the default)")
    String jobs;

    @Option(names = "--out", paramLabel = "FILE", defaultValue = "-",
            description = "where the outcomes go (- for standard"
            + " output, the default)")
    String out;

    @Option(names = "--threads", paramLabel = "N", description = "jobs at once (default: the machine's cores)")
    Integer threads;

    @Option(names = "--classpath", paramLabel = "DIR_OR_JAR", split = "${sys:path.separator}",
            description = "folders and jars with your compiled controllers")
    List<Path> classpath = new ArrayList<>();

    @Option(names = "--controller", paramLabel = "NAME", description = "the controller of a job that names none")
    String controller;

    @Option(names = "--arena", paramLabel = "NAME_OR_FILE", description = "the arena of a job that names none")
    String arena;

    @Option(names = "--robot-file", paramLabel = "FILE",
            description = "the robot for every job's arena robot lines that name none: a robot file or a bundled robot")
    String robotFile;

    @Option(names = "--seconds", paramLabel = "S", defaultValue = "60", converter = CliNumbers.PositiveSeconds.class,
            description = "simulated seconds of a job that"
            + " says none (default ${DEFAULT-VALUE})")
    double seconds;

    @Option(names = "--ordered", description = "write the outcomes in the jobs' order (by default each as it finishes)")
    boolean ordered;

    @Option(names = "--shard", paramLabel = "K/N",
            description = "evaluate only the jobs of slice K of N (lines K-1, K-1+N,"
            + " ...), for a Slurm job array or a Kubernetes Indexed Job; join the slices' outputs with --join")
    String shard;

    @Option(names = "--join", paramLabel = "FILE", arity = "1..*",
            description = "instead of evaluating: join outputs of"
            + " --shard slices into one, in the jobs' order (the same as one machine's --ordered output)")
    List<Path> join;

    @Option(names = "--contained",
            description = "check the controllers against the allowlist (docs/controller-rules.md)"
            + " instead of running them as your own code")
    boolean contained;

    @Override
    public Integer call() throws Exception {
        PrintStream sink = out.equals("-") ? System.out
                : new PrintStream(Files.newOutputStream(Path.of(out)), true, StandardCharsets.UTF_8);
        try {
            if (join != null) {
                return EvaluateJson.join(join, sink);
            }
            GradePlan.Shard slice = shard == null ? GradePlan.Shard.ALL : GradePlan.Shard.parse(shard);
            int n = threads != null ? threads : Runtime.getRuntime().availableProcessors();
            // A running count on a terminal (standard input and output both one); none in a pipe.
            boolean progress = System.console() != null;
            return evaluate(slice, n, sink, progress);
        } finally {
            if (sink != System.out) {
                sink.close();
            }
        }
    }

    private int evaluate(GradePlan.Shard slice, int n, PrintStream sink, boolean progress) throws IOException,
            InterruptedException {
        AtomicInteger done = new AtomicInteger();
        AtomicInteger failed = new AtomicInteger();
        AtomicInteger bad = new AtomicInteger();
        String[] firstBad = {""};
        Map<Long, String> pending = new TreeMap<>();
        long[] nextOrdered = {-1};
        List<Long> order = new ArrayList<>();
        Object lock = new Object();
        long start = System.nanoTime();
        org.kheperasim.sim.arena.RobotKind robot =
                robotFile == null ? null : org.kheperasim.sim.arena.RobotKind.of(robotFile);
        try (Evaluator evaluator = new Evaluator(classpath, !contained, n).robot(robot);
                BufferedReader in = jobs.equals("-")
                        ? new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8))
                        : jobFile(Path.of(jobs))) {
            BoundedLines lines = new BoundedLines(in, MAX_JOB_CHARS, (l, what) -> new InputFileException(
                    jobs.equals("-") ? "standard input" : jobs, l, what + " (a job is one JSON object on one line)"));
            String line;
            long index = -1;
            while ((line = lines.next()) != null) {
                index++;
                if (line.isBlank() || line.stripLeading().startsWith("#") || index % slice.n() != slice.k() - 1) {
                    continue;
                }
                synchronized (lock) {
                    order.add(index);
                }
                Job job;
                try {
                    job = EvaluateJson.job(index, line, controller, arena, seconds);
                } catch (IllegalArgumentException e) {
                    if (bad.incrementAndGet() == 1) {
                        firstBad[0] = "line " + (index + 1) + ": " + e.getMessage();
                    }
                    emit(lock, pending, order, nextOrdered, sink, index,
                            EvaluateJson.error(index, EvaluateJson.idOf(line),
                                    "line " + (index + 1) + ": " + e.getMessage()));
                    continue;
                }
                long i = index;
                evaluator.submit(job, o -> {
                    if (!o.ok()) {
                        failed.incrementAndGet();
                    }
                    emit(lock, pending, order, nextOrdered, sink, i, EvaluateJson.outcome(o));
                    int d = done.incrementAndGet();
                    if (progress) {
                        System.err.printf(Locale.ROOT, "\r%d jobs done, %.1f a second   ", d,
                                d / ((System.nanoTime() - start) / 1e9));
                    }
                });
            }
        }
        if (ordered) {
            synchronized (lock) {
                flushOrdered(pending, order, nextOrdered, sink, true);
            }
        }
        if (progress) {
            System.err.println();
        }
        if (bad.get() > 0) {
            System.err.println(ToolErrors.prefix(ErrorLine.TOOL) + bad.get() + " job line" + (bad.get() == 1 ? "" : "s")
                    + " could not be read (first: " + Shown.visible(firstBad[0]) + "); their outcome lines say why");
        }
        return bad.get() > 0 ? ExitCodes.BAD_INPUT : failed.get() > 0 ? ExitCodes.FAILED : ExitCodes.OK;
    }

    /**
     * @param file a job file: a regular file, or a pipe (read as it comes, like standard input); a folder is refused
     * @return a reader of it
     */
    private static BufferedReader jobFile(Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw new InputFileException(file.toString(), 0,
                    "this is a folder; give a job file (JSON job lines), or - for"
                    + " standard input");
        }
        return Files.newBufferedReader(file, StandardCharsets.UTF_8);
    }

    /** Write an outcome now, or (--ordered) once every job before it has been written. */
    private void emit(Object lock, Map<Long, String> pending, List<Long> order, long[] next,
            PrintStream sink, long index,
            String json) {
        synchronized (lock) {
            if (!ordered) {
                sink.println(json);
                sink.flush();
                return;
            }
            pending.put(index, json);
            flushOrdered(pending, order, next, sink, false);
        }
    }

    private static void flushOrdered(Map<Long, String> pending, List<Long> order, long[] next,
            PrintStream sink, boolean all) {
        while (next[0] + 1 < order.size()) {
            long want = order.get((int) (next[0] + 1));
            String json = pending.remove(want);
            if (json == null) {
                if (all) {
                    throw new UncheckedIOException(new IOException("no outcome for job " + want));
                }
                return;
            }
            sink.println(json);
            next[0]++;
        }
        sink.flush();
    }
}
