package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.sandbox.BoxProbe;

/**
 * Grading loses nothing: {@code kill -9} of the grader halfway leaves no child JVM behind (the boxes
 * die with their parent, a child outside a box ends when its grader's pipe does), SIGTERM neither;
 * started again on the same folder, grade makes only the runs its journal lacks and writes the same
 * report, byte for byte, as a grading that was never interrupted.
 */
class GradeResumeTest {
    private static final List<String> STUDENTS = List.of("alice", "bob", "carol", "dave");

    @TempDir
    Path dir;

    /**
     * In the sandbox where there is one (CI has it, as root), else without: the runs die with their grader
     * either way (bubblewrap, or the end of the pipe that is the child's lifeline), which
     * {@link #aRunEndsSoonAfterItsGraderIsKilled} checks both ways.
     */
    @Test
    @Timeout(value = 600, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void killedTwiceThenResumedTheGradingWritesTheSameReport() throws Exception {
        boolean box = BoxProbe.unavailable().isEmpty();
        if (!box && "true".equals(System.getenv("CI"))) {
            Hostile.requireBox();
        }
        Path subs = dir.resolve("subs");
        for (String s : STUDENTS) {
            Path to = Files.createDirectories(subs.resolve(s));
            try (Stream<Path> files = Files.list(Path.of("src/test/resources/grade", s))) {
                for (Path f : files.toList()) {
                    Files.copy(f, to.resolve(f.getFileName()));
                }
            }
        }
        // The grading never interrupted, the reference, made in this JVM beside the interrupted ones (child JVMs, which
        // mostly wait: for their JVMs to start, for the journal to reach a count); the two share no folder.
        Path whole = dir.resolve("whole");
        Path resumed = dir.resolve("resumed");
        ExecutorService beside = Executors.newSingleThreadExecutor();
        try {
            Future<ReportFiles.Report> reference = beside.submit(() -> Grader.grade(options(subs, whole, box)));
            interrupt(subs, resumed, box, 2, true);   // kill -9
            interrupt(subs, resumed, box, 4, false);  // SIGTERM, with half the runs still to make
            Grader.grade(options(subs, resumed, box));
            reference.get();
        } finally {
            beside.shutdown(); // after a failure above, the reference grading still ends before its folder is deleted
            beside.awaitTermination(120, TimeUnit.SECONDS);
        }

        List<String> lines = Files.readAllLines(resumed.resolve(Journal.FILE));
        assertEquals(1 + 8, lines.size(), "the journal holds each run once: " + lines);
        List<String> files = ReportFolder.files(whole);
        assertEquals(files, ReportFolder.files(resumed));
        assertTrue(files.contains("img/dave__maze__s2.png"), files.toString());
        for (String f : files) {
            assertArrayEquals(Files.readAllBytes(whole.resolve(f)), Files.readAllBytes(resumed.resolve(f)), f);
        }
    }

    /** A run that would go on for minutes ends within seconds of its grader's kill -9. */
    @ParameterizedTest(name = "in the sandbox: {0}")
    @ValueSource(booleans = {true, false})
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aRunEndsSoonAfterItsGraderIsKilled(boolean box) throws Exception {
        if (box) {
            Hostile.requireBox();
        }
        Path subs = dir.resolve("subs");
        Files.createDirectories(subs.resolve("slow"));
        Files.writeString(subs.resolve("slow/Slow.java"), """
                import org.kheperasim.api.*;

                public class Slow extends Controller {
                    private long sum;

                    @Override
                    protected void doWork() {
                        for (long i = 0; i < 400_000_000L; i++) {
                            sum += i ^ (sum >>> 3); // a second of thinking, well under the hang timeout
                        }
                        setSpeeds((int) (sum & 3), 3);
                        sleepMillis(100);
                    }
                }
                """);
        Path out = dir.resolve("out");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:TieredStopAtLevel=1", "-cp",
                System.getProperty("java.class.path"), "org.kheperasim.sim.cli.Main", "grade", "--submissions", subs.toString(),
                "--arenas", "maze", "--seeds", "1", "--seconds", "600", "--wall-limit", "600", "--out", out.toString()));
        if (!box) {
            cmd.add("--no-sandbox");
        }
        Process grader = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(dir.resolve("grade.log").toFile()).start();
        List<ProcessHandle> runs = List.of();
        long deadline = System.nanoTime() + 120_000_000_000L;
        long started = System.nanoTime();
        while (runs.isEmpty()) {
            if (!grader.isAlive() || System.nanoTime() > deadline) {
                grader.destroyForcibly();
                fail("no run started: " + Files.readString(dir.resolve("grade.log")));
            }
            runs = runs(grader, out);
            Thread.sleep(50);
        }
        String seen = runs.stream().map(h -> h.pid() + " " + h.info()).toList().toString();
        double seenAfter = (System.nanoTime() - started) / 1e9;
        Thread.sleep(3000); // the run is under way
        if (!runs.stream().allMatch(ProcessHandle::isAlive)) {
            grader.waitFor(10, TimeUnit.SECONDS); // the grader says how the run ended
            grader.destroyForcibly();
            fail("the run ended while its grader lived: " + seen + " (seen " + seenAfter + " s after grade started)\n"
                    + Files.readString(dir.resolve("grade.log")));
        }
        grader.destroyForcibly();
        grader.waitFor();
        long killedAt = System.nanoTime();
        while (runs.stream().anyMatch(ProcessHandle::isAlive) || !orphans(out).isEmpty()) {
            if (System.nanoTime() - killedAt > 15_000_000_000L) {
                fail("kill -9 of grade left its run going for 15 s: " + orphans(out));
            }
            Thread.sleep(100);
        }
    }

    /**
     * Simulated seconds a run: long enough that the runs after the one the test waits for are still going
     * when it looks (grade journals, judges and starts runs beside each other, and on a busy machine the
     * test's own polling may lag a whole run behind).
     */
    private static final double SECONDS = 150;

    private static Grader.Options options(Path subs, Path out, boolean box) {
        return new Grader.Options(subs, List.of("maze"), 2, 2, out, GradePlan.Shard.ALL, 256, 120, 5, SECONDS, false,
                new PrintStream(OutputStream.nullOutputStream()), false, box, false);
    }

    /**
     * Start grade in a JVM of its own, wait until its journal holds {@code runs} runs, then kill it
     * (SIGKILL or SIGTERM) and check that none of its runs outlives it.
     */
    private static void interrupt(Path subs, Path out, boolean box, int runs, boolean kill9) throws Exception {
        // Both compilers, not C1 only as elsewhere: the grader must still be running when it is interrupted,
        // and C1's quicker start let CI's grade end between two polls.
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp",
                System.getProperty("java.class.path"), "org.kheperasim.sim.cli.Main", "grade", "--submissions", subs.toString(),
                "--arenas", "maze", "--seeds", "2", "--seconds", String.valueOf(SECONDS), "--jobs", "2", "--out", out.toString()));
        if (!box) {
            cmd.add("--no-sandbox");
        }
        Process grader = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(out.resolveSibling("grade.log").toFile())
                .start();
        Path journal = out.resolve(Journal.FILE);
        long deadline = System.nanoTime() + 240_000_000_000L;
        List<ProcessHandle> children = List.of();
        // The kill -9 waits for runs to be going, to check that none outlives its grader; the SIGTERM only for the
        // journal (aRunEndsSoonAfterItsGraderIsKilled checks SIGTERM's runs): on a quick JVM the last runs of a
        // resumed grading can end between two polls of the process table.
        while (journalRuns(journal) < runs || kill9 && children.isEmpty()) {
            if (!grader.isAlive()) {
                fail("grade ended before it could be interrupted: " + Files.readString(out.resolveSibling("grade.log")));
            }
            if (System.nanoTime() > deadline) {
                grader.destroyForcibly();
                fail("grade made fewer than " + runs + " runs in 240 s");
            }
            children = runs(grader, out);
            Thread.sleep(50);
        }
        if (kill9) {
            assertFalse(children.isEmpty(), "runs were going when grade was stopped");
        }
        if (kill9) {
            grader.destroyForcibly();
        } else {
            grader.destroy();
        }
        grader.waitFor();
        long gone = System.nanoTime() + 20_000_000_000L;
        while (children.stream().anyMatch(ProcessHandle::isAlive) || !orphans(out).isEmpty()) {
            if (System.nanoTime() > gone) {
                fail((kill9 ? "kill -9" : "SIGTERM") + " of grade left runs behind: " + orphans(out));
            }
            Thread.sleep(100);
        }
        assertTrue(Files.exists(journal));
    }

    /**
     * The grader's runs: its JVMs that run {@code GradedRun} or {@code WorkerMain} with a command line naming the
     * report folder. A child the grader has forked but not yet exec'd (the sandbox's {@code ldd} probe, a
     * starting run) still shows the grader's own command line, {@code Main grade ... --out FOLDER}, so the
     * folder alone does not tell a run.
     */
    private static List<ProcessHandle> runs(Process grader, Path out) {
        String folder = out.toAbsolutePath().toString();
        return grader.descendants().filter(h -> h.info().command().map(c -> c.endsWith("java")).orElse(false)
                && h.info().commandLine().map(c -> c.contains(folder) && RUN.matcher(c).find()).orElse(false)).toList();
    }

    /** A graded run's JVM, in a JVM of its own or a warm worker (the grader itself runs {@code grade}). */
    private static final Pattern RUN = Pattern.compile("org\\.kheperasim\\.sim\\.grade\\.(GradedRun|WorkerMain) ");

    /** Every process whose command line names the report folder (a run's classpath lies under it). */
    private static List<String> orphans(Path out) {
        String folder = out.toAbsolutePath().toString();
        return ProcessHandle.allProcesses().filter(ProcessHandle::isAlive)
                .map(h -> h.pid() + " " + h.info().commandLine().orElse("")).filter(c -> c.contains(folder)).toList();
    }

    private static int journalRuns(Path journal) throws IOException {
        return Files.exists(journal) ? (int) Files.readAllLines(journal).stream().filter(l -> l.startsWith("{\"index\"")).count() : 0;
    }

}
