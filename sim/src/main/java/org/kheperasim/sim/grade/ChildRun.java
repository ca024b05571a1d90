package org.kheperasim.sim.grade;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

/**
 * Makes one graded run in a child JVM: {@code java -Xmx… org.kheperasim.sim.cli.Main run … --json},
 * with the heap limit, the simulated-time limit and a wall-clock limit after which the child is
 * killed. The child runs the controller contained (docs/controller-rules.md); what it prints, its
 * exit status and whether it was killed become a {@link RunRecord} ({@link ChildResults}).
 */
final class ChildRun {
    /** What every run of a grading shares. */
    record Limits(int heapMb, double wallSeconds, double hangSeconds, Double seconds, long sampleMillis, int processors) {
    }

    /**
     * What came back.
     *
     * @param record      the run as the report holds it
     * @param wallSeconds real time it took, s
     * @param trace       its trace, or null when there is none
     */
    record Outcome(RunRecord record, double wallSeconds, Path trace) {
    }

    private ChildRun() {
    }

    /**
     * @param job  the run
     * @param sub  the student's submission (runnable)
     * @param lim  the limits
     * @param runs where the run's trace goes
     * @return what came back
     * @throws IOException if the child cannot be started
     */
    static Outcome run(GradePlan.Job job, Submission sub, Limits lim, Path runs) throws IOException {
        Path trace = runs.resolve(ReportFiles.runId(job) + ".trace");
        Files.deleteIfExists(trace);
        // Native access for JNA (the controller threads' core, see host.CpuAffinity): Java 22+ warns without it.
        List<String> cmd = new ArrayList<>(List.of(java(), "--enable-native-access=ALL-UNNAMED", "-Xmx" + lim.heapMb() + "m", "-XX:+UseSerialGC",
                "-XX:ActiveProcessorCount=" + lim.processors(), "-Djava.awt.headless=true",
                "-cp", System.getProperty("java.class.path"), "org.kheperasim.sim.cli.Main", "run",
                "--arena", arenaArg(job.arena()), "--classpath", sub.classpath().toString(),
                "--controller", sub.controller(), "--seed", Long.toString(job.seed()), "--json", "--quiet",
                "--hang-timeout", format(lim.hangSeconds()), "--trace", trace.toString(),
                "--sample-ms", Long.toString(lim.sampleMillis())));
        if (lim.seconds() != null) {
            cmd.add("--seconds");
            cmd.add(format(lim.seconds()));
        }
        long start = System.nanoTime();
        Process p = new ProcessBuilder(cmd).redirectInput(ProcessBuilder.Redirect.from(nullFile())).start();
        Tail out = new Tail(p.getInputStream(), 1 << 20, "grade-out-" + job.index());
        Tail err = new Tail(p.getErrorStream(), 64 << 10, "grade-err-" + job.index());
        boolean killed = false;
        try {
            if (!p.waitFor((long) (lim.wallSeconds() * 1000), TimeUnit.MILLISECONDS)) {
                killed = true;
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
                p.waitFor(30, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            p.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new IOException("grading was interrupted", e);
        }
        double wall = (System.nanoTime() - start) / 1e9;
        // The submission's class folder lies under --out: its files are named from there on, so that
        // the report does not depend on where it was written (shards merge byte for byte into it).
        String classes = sub.classpath().toAbsolutePath().normalize() + File.separator;
        String absolute = sub.classpath().toAbsolutePath() + File.separator;
        String given = sub.classpath() + File.separator;
        RunRecord r = ChildResults.record(job, sub.controller(), killed, lim.wallSeconds(), p.exitValue(),
                strip(out.text(5000), classes, absolute, given), strip(err.text(5000), classes, absolute, given));
        return new Outcome(r, wall, Files.isRegularFile(trace) ? trace : null);
    }

    /** A file path stays a path the child can find whatever its working folder; a bundled name stays a name. */
    private static String arenaArg(String arena) {
        Path p = Path.of(arena);
        return Files.isRegularFile(p) ? p.toAbsolutePath().toString() : arena;
    }

    private static String java() {
        return Path.of(System.getProperty("java.home"), "bin", "java").toString();
    }

    private static File nullFile() {
        return new File(File.separatorChar == '\\' ? "NUL" : "/dev/null");
    }

    private static String format(double d) {
        return String.format(Locale.ROOT, "%s", d == StrictMath.rint(d) ? Long.toString((long) d) : Double.toString(d));
    }

    /** @return {@code text} with each of the folder prefixes taken out (the longest first, as given) */
    private static String strip(String text, String... prefixes) {
        for (String p : prefixes) {
            text = text.replace(p, "");
        }
        return text;
    }
}
