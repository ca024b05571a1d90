package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.sandbox.BoxProbe;

/**
 * Grading on warm workers (one worker JVM per submission, each run with fresh class loaders) writes
 * the report a grading with one JVM per run ({@code --worker-runs 1}) writes, byte for byte, for good
 * and careless submissions alike; what a run leaves in its worker (statics, a thread that spins)
 * changes no later run; a run killed at its wall-clock limit takes its worker with it, and the
 * submission's next run gets a new one. In the sandbox where there is one (CI has it, as root).
 */
class WarmWorkerGradingTest {
    private static final Path SUBMISSIONS = Path.of("src", "test", "resources", "grade");
    private static final Pattern MADE = Pattern.compile("made (\\d+) runs on (\\d+) worker JVMs \\((\\d+) replaced");

    @TempDir
    Path dir;

    @Test
    @Timeout(value = 480, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void gradingOnWarmWorkersWritesTheSameReportAsOneJvmPerRun() throws Exception {
        requireBoxInCi();
        Path subs = copySubmissions(List.of("alice", "carol", "erin", "frank", "grace", "ivan"));
        Hostile.poolSpinner(subs.resolve("paula"));
        keeper(subs.resolve("kim"));
        // One seed in two arenas: every submission that runs makes two runs, so each worker serves more than one.
        String[] common = {"--submissions", subs.toString(), "--arenas", "maze", "lab", "--seeds", "1", "--seconds", "20",
            "--jobs", "2", "--hang-timeout", "3", "--wall-limit", "120", "--heap-mb", "128"};
        Path warm = dir.resolve("warm");
        Path one = dir.resolve("one");
        String printed = gradeBesideOneJvmPerRun(common, warm, one);

        Map<String, String> status = ReportFiles.readCsv(warm.resolve("results.csv")).stream().collect(Collectors.toMap(
                RunRecord::student, r -> r.status().word(), (a, b) -> a.equals(b) ? a : a + "/" + b, TreeMap::new));
        // paula's pool is refused at load, as in a JVM of her own; kim's spinning thread is stopped with his run.
        assertEquals(Map.of("alice", "ok", "carol", "ok", "erin", "compile_failed", "frank", "threw", "grace", "hung",
                "ivan", "exceeded_memory", "kim", status.get("kim"), "paula", "broke_rule"), status, printed);
        sameReport(one, warm);
        int[] made = made(printed);
        assertEquals(14, made[0], printed); // erin's 2 runs need no JVM
        assertTrue(made[1] < made[0], "the runs share worker JVMs: " + printed);
        assertTrue(made[2] >= 2, "grace's hung runs and ivan's runs out of memory cost their workers: " + printed);
    }

    @Test
    @Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void whatARunLeavesInItsWorkerChangesNoLaterRun() throws Exception {
        requireBoxInCi();
        Path subs = dir.resolve("subs");
        counter(subs.resolve("cole"));
        keeper(subs.resolve("kim"));
        namer(subs.resolve("nora"));
        String[] common = {"--submissions", subs.toString(), "--arenas", "lab", "--seeds", "2", "--seconds", "20", "--jobs", "2",
            "--hang-timeout", "3", "--wall-limit", "120", "--heap-mb", "128"};
        Path warm = dir.resolve("warm");
        Path one = dir.resolve("one");
        String printed = gradeBesideOneJvmPerRun(common, warm, one);

        sameReport(one, warm);
        Map<String, List<String>> status = ReportFiles.readCsv(warm.resolve("results.csv")).stream().collect(Collectors.groupingBy(
                RunRecord::student, TreeMap::new, Collectors.mapping(r -> r.status().word(), Collectors.toList())));
        assertEquals(Map.of("cole", List.of("ok", "ok"), "kim", List.of("hung", "hung"), "nora", List.of("threw", "threw")),
                status, printed);
        for (RunRecord r : ReportFiles.readCsv(warm.resolve("results.csv"))) {
            if (r.student().equals("nora")) {
                assertTrue(r.detail().startsWith("java.lang.IllegalStateException: my helper was Thread-"), r.detail());
            }
        }
        // cole keeps state in statics, nora numbers an unnamed thread: each shares one worker over two runs, each run
        // as in a JVM of its own. kim's thread spins on after his run (it hangs): each of his runs gets a new worker.
        int[] made = made(printed);
        assertEquals(List.of(6, 4, 1), List.of(made[0], made[1], made[2]), printed);
    }

    @Test
    @Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aRunKilledAtItsWallLimitTakesItsWorkerAndTheNextRunGetsAFreshOne() throws Exception {
        requireBoxInCi();
        Path subs = dir.resolve("subs");
        slowpoke(subs.resolve("sam"));
        Path near = dir.resolve("near.arena");
        // The lab, with the robot facing its top wall from a few millimetres away.
        Files.writeString(near, String.join("\n", "khepera-arena 1", "name near", "size 1219.2 1219.2", "robot 609.6 1178 90",
                "wall 0 4 1219.2 4 8", "wall 0 1215.2 1219.2 1215.2 8", "wall 4 0 4 1219.2 8", "wall 1215.2 0 1215.2 1219.2 8",
                "region all 0 0 1219.2 1219.2", "time-limit 600", "task cover 50", ""));
        String[] common = {"--submissions", subs.toString(), "--arenas", near.toString(), "lab", "--seeds", "1", "--seconds",
            "20", "--jobs", "1", "--hang-timeout", "5", "--wall-limit", "8", "--heap-mb", "128"};
        Path warm = dir.resolve("warm");
        Path one = dir.resolve("one");
        String printed = gradeBesideOneJvmPerRun(common, warm, one);

        List<RunRecord> runs = ReportFiles.readCsv(warm.resolve("results.csv"));
        assertEquals(RunStatus.HUNG, runs.get(0).status(), runs.toString());
        assertEquals("no result within the wall-clock limit of 8 s; the run was killed", runs.get(0).detail());
        assertEquals(RunStatus.OK, runs.get(1).status(), runs.toString());
        assertEquals(20, runs.get(1).simulatedSeconds(), 1e-9);
        sameReport(one, warm);
        int[] made = made(printed);
        assertEquals(List.of(2, 2, 1), List.of(made[0], made[1], made[2]), printed);
    }

    /**
     * Every file of the report the same, byte for byte, but for what the report already says varies:
     * the moment a run that allocates without bound is stopped depends on the collector, so its
     * simulated seconds (and its page) may differ; its status, points and detail may not.
     */
    private static void sameReport(Path expected, Path actual) throws IOException {
        List<String> files = ReportFolder.files(expected);
        assertEquals(files, ReportFolder.files(actual));
        List<RunRecord> e = ReportFiles.readCsv(expected.resolve("results.csv"));
        List<RunRecord> a = ReportFiles.readCsv(actual.resolve("results.csv"));
        assertEquals(e.size(), a.size());
        List<String> varying = new ArrayList<>();
        for (int i = 0; i < e.size(); i++) {
            RunRecord x = e.get(i);
            RunRecord y = a.get(i);
            if (x.status() == RunStatus.EXCEEDED_MEMORY && y.status() == RunStatus.EXCEEDED_MEMORY) {
                assertEquals(List.of(x.student(), x.arena(), x.seed(), x.detail(), x.picture(), x.page()),
                        List.of(y.student(), y.arena(), y.seed(), y.detail(), y.picture(), y.page()));
                varying.add(x.page());
                varying.add(x.picture());
            } else {
                assertEquals(x, y);
            }
        }
        for (String f : files) {
            if (varying.contains(f)) {
                continue;
            }
            byte[] want = Files.readAllBytes(expected.resolve(f));
            byte[] got = Files.readAllBytes(actual.resolve(f));
            if (varying.isEmpty() || !(f.equals("results.csv") || f.equals("results.json"))) {
                assertArrayEquals(want, got, f);
            }
        }
    }

    /** A controller that keeps state in statics (its own and a helper's) and leaves a thread spinning: it hangs. */
    private static void keeper(Path folder) throws IOException {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve("Keeper.java"), """
                import org.kheperasim.api.*;

                public class Keeper extends Controller {
                    private static int runs;
                    private static Thread spinner;
                    private int step;

                    @Override
                    protected void doWork() {
                        if (step++ == 0) {
                            runs++;
                            Memo.seen++;
                            if (spinner == null) {
                                spinner = new Thread(() -> {
                                    while (true) {
                                        Memo.spins++;
                                    }
                                });
                                spinner.setDaemon(true);
                                spinner.start();
                            }
                        }
                        int turn = 3 * (runs + Memo.seen - 2); // 0 in a JVM of its own
                        setSpeeds(proximity(IrSensor.FRONT_LEFT) > 400 ? -4 : 5 + turn, 5 - turn);
                        sleepMillis(100);
                    }
                }

                class Memo {
                    static int seen;
                    static volatile long spins;
                }
                """);
    }

    /** A controller that starts an unnamed thread and throws its name. */
    private static void namer(Path folder) throws IOException {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve("Namer.java"), """
                import org.kheperasim.api.*;

                public class Namer extends Controller {
                    private int step;

                    @Override
                    protected void doWork() {
                        if (++step == 5) {
                            Thread t = new Thread(() -> { });
                            t.start();
                            try {
                                t.join();
                            } catch (InterruptedException e) {
                                return;
                            }
                            throw new IllegalStateException("my helper was " + t.getName());
                        }
                        setSpeeds(3, 3);
                        sleepMillis(100);
                    }
                }
                """);
    }

    /** A controller that counts its runs in a static field and drives by the count. */
    private static void counter(Path folder) throws IOException {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve("Counter.java"), """
                import org.kheperasim.api.*;

                public class Counter extends Controller {
                    private static int starts;
                    private static final java.util.List<Integer> SEEN = new java.util.ArrayList<>();
                    private boolean started;

                    @Override
                    protected void doWork() {
                        if (!started) {
                            started = true;
                            starts++;
                            SEEN.add(starts);
                        }
                        int turn = 2 * (starts - 1) + SEEN.size() - 1; // 0 in a JVM of its own
                        setSpeeds(proximity(IrSensor.FRONT_RIGHT) > 400 ? -4 : 4 + turn, 4 - turn);
                        sleepMillis(50);
                    }
                }
                """);
    }

    /** A controller that, facing a wall at its start, works in real time between its API calls, for ever. */
    private static void slowpoke(Path folder) throws IOException {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve("Slowpoke.java"), """
                import org.kheperasim.api.*;

                public class Slowpoke extends Controller {
                    private int step;
                    private boolean slow;
                    private long sink;

                    @Override
                    protected void doWork() {
                        if (step++ == 0) {
                            slow = proximity(IrSensor.FRONT_LEFT) > 500 || proximity(IrSensor.FRONT_RIGHT) > 500;
                        }
                        if (slow) {
                            for (int i = 0; i < 5_000_000; i++) {
                                sink += i * 31L ^ sink;
                            }
                            sleepMillis(1);
                        } else {
                            setSpeeds(4, 3);
                            sleepMillis(100);
                        }
                    }
                }
                """);
    }

    /** @return the runs made, the worker JVMs started and those replaced, as the grader's progress says */
    private static int[] made(String printed) {
        Matcher m = MADE.matcher(printed);
        assertTrue(m.find(), "the grader says how the runs were made: " + printed);
        return new int[] {Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)), Integer.parseInt(m.group(3))};
    }

    private static void requireBoxInCi() {
        if ("true".equals(System.getenv("CI"))) {
            Hostile.requireBox();
        }
    }

    private Path copySubmissions(List<String> students) throws IOException {
        Path subs = dir.resolve("submissions");
        for (String s : students) {
            Path to = Files.createDirectories(subs.resolve(s));
            try (Stream<Path> files = Files.list(SUBMISSIONS.resolve(s))) {
                for (Path f : files.toList()) {
                    Files.copy(f, to.resolve(f.getFileName()));
                }
            }
        }
        return subs;
    }


    /**
     * Grades on warm workers into {@code warm} (in this JVM, {@link #grade}) while the reference grading, one JVM per run
     * ({@code --worker-runs 1}), goes into {@code one} beside it, in a JVM of its own: the two are independent, and most of
     * each is waiting (hang timeouts, wall-clock limits, JVMs starting). @return what the warm grading printed
     */
    private String gradeBesideOneJvmPerRun(String[] common, Path warm, Path one) throws IOException, InterruptedException {
        try (ChildGrading reference = ChildGrading.start(dir.resolve("one.log"),
                ReportFolder.concat(common, "--out", one.toString(), "--worker-runs", "1"))) {
            String printed = grade(ReportFolder.concat(common, "--out", warm.toString()));
            reference.await(240);
            return printed;
        }
    }

    /** Grades (in the sandbox where there is one) through the command line; returns what it printed, progress included. */
    private static String grade(String... args) {
        boolean box = BoxProbe.unavailable().isEmpty();
        String[] full = Stream.concat(Stream.concat(Stream.of("grade"), Stream.of(args)),
                box ? Stream.empty() : Stream.of("--no-sandbox")).toArray(String[]::new);
        PrintStream oldOut = System.out;
        PrintStream oldErr = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        int code;
        try {
            PrintStream both = new PrintStream(o, true, StandardCharsets.UTF_8);
            System.setOut(both);
            System.setErr(both);
            code = org.kheperasim.sim.cli.Main.commandLine().execute(full);
        } finally {
            System.setOut(oldOut);
            System.setErr(oldErr);
        }
        String text = o.toString(StandardCharsets.UTF_8);
        assertEquals(0, code, text);
        return text;
    }
}
