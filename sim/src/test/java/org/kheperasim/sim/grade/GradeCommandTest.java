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
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.cli.Main;

/**
 * {@code grade} end to end, each run in a child JVM: a class of test submissions (good ones in every
 * controller style, one that does not compile, one that throws, hangs, calls System.exit, allocates
 * without bound, and one handed in as a .class file) gets the right status each, and the CSV and
 * JSON read back to the same runs, each replayed run has its page; two shards merged give the same
 * report, pages and all, as one grading.
 */
class GradeCommandTest {
    private static final Path SUBMISSIONS = Path.of("src", "test", "resources", "grade");

    @TempDir
    Path dir;

    @Test
    @Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void everySubmissionGetsItsStatusAndTheReportReadsBack() throws IOException {
        Path subs = copySubmissions(List.of("alice", "bob", "carol", "dave", "erin", "frank", "grace", "heidi", "ivan"));
        addClassSubmission(subs.resolve("judy"));
        Files.createDirectories(subs.resolve("zed")); // handed in nothing
        Path out = dir.resolve("report");
        String printed = grade("--submissions", subs.toString(), "--arenas", "maze", "--seeds", "1", "--seconds", "20",
                "--jobs", "2", "--out", out.toString(), "--hang-timeout", "5", "--wall-limit", "90", "--heap-mb", "128");

        List<RunRecord> csv = ReportFiles.readCsv(out.resolve("results.csv"));
        Map<String, String> status = csv.stream().collect(Collectors.toMap(RunRecord::student, r -> r.status().word(),
                (a, b) -> a, TreeMap::new));
        Map<String, String> expected = new TreeMap<>(Map.of("alice", "ok", "bob", "ok", "carol", "ok", "dave", "ok",
                "judy", "ok", "erin", "compile_failed", "frank", "threw", "grace", "hung", "heidi", "broke_rule",
                "ivan", "exceeded_memory"));
        expected.put("zed", "nothing_handed_in");
        assertEquals(expected, status, printed);

        ReportFiles.Report json = ReportFiles.read(out.resolve("results.json"));
        assertEquals(csv, json.runs(), "the CSV and the JSON hold the same runs");
        assertEquals(List.of("maze"), json.plan().arenas());
        assertEquals(11, json.plan().students().size());
        for (RunRecord r : csv) {
            assertEquals(100, r.max(), r.toString());
            if (r.status() == RunStatus.OK) {
                assertEquals(20, r.simulatedSeconds(), 1e-9, r.toString());
            }
            if (r.status() == RunStatus.COMPILE_FAILED) {
                assertTrue(r.detail().startsWith("Broken.java:7:"), r.detail());
                assertEquals("", r.picture());
            } else if (r.status() == RunStatus.NOTHING_HANDED_IN) {
                assertEquals("the folder is empty", r.detail());
                assertEquals("", r.picture());
            } else {
                assertTrue(Files.size(out.resolve(r.picture())) > 500, r.picture());
                // Every run that was replayed is a page that replays it, linked from its thumbnail.
                assertEquals("pages/" + r.student() + "__maze__s1.html", r.page());
                assertTrue(Files.readString(out.resolve(r.page())).contains("\"title\":\"" + r.student() + ": "), r.page());
            }
        }
        // What frank's run threw, and where in his code: in every format the instructor sends back.
        assertTrue(byStudent(csv, "frank").detail().startsWith("java.lang.IllegalStateException: frank's controller gave up"
                + " at step 20 at Thrower.doWork(Thrower.java:12)"), byStudent(csv, "frank").detail());
        for (String file : new String[] {"results.csv", "results.json", "report.txt", "index.html"}) {
            assertTrue(Files.readString(out.resolve(file)).contains("at Thrower.doWork(Thrower.java:12)"), file);
        }
        assertTrue(!byStudent(csv, "grace").detail().contains("real time"), "no machine's seconds: " + byStudent(csv, "grace"));
        assertTrue(byStudent(csv, "heidi").detail().contains("called System.exit(3)"));
        assertTrue(byStudent(csv, "grace").detail().contains("stopped making API calls"));
        assertTrue(byStudent(csv, "ivan").detail().contains("allocated without bound"));
        assertTrue(byStudent(csv, "alice").points() > 4, "alice explores more than her start cell");

        String html = Files.readString(out.resolve("index.html"));
        assertTrue(html.contains("<a href=\"pages/alice__maze__s1.html\" title=\"watch the run\"><img src=\"img/alice__maze__s1.png\""),
                html);
        // frank's page shows his failure as the report tells it, when it happened.
        String frank = Files.readString(out.resolve("pages/frank__maze__s1.html"));
        assertTrue(frank.matches("(?s).*\"failures\":\\[\\{\"robot\":0,\"t\":20\\d\\d(\\.\\d+)?,\"status\":\"failed\",\"message\":"
                + "\"java.lang.IllegalStateException: frank's controller gave up at step 20 at Thrower.doWork\\(Thrower.java:12\\)\"}].*"),
                "frank's page names his line, at the time he threw");
        String timings = Files.readString(out.resolve("timings.csv"));
        assertTrue(timings.startsWith("run,status,wall_s,page_s\n"), timings);
        assertTrue(html.contains("failed to compile"), html);
        assertTrue(printed.contains("11 runs: 5 ok, 1 failed to compile, 1 nothing handed in, 1 threw, 1 hung, 1 exceeded memory,"
                + " 1 broke a rule;"
                + (org.kheperasim.sim.sandbox.BoxProbe.unavailable().isEmpty() ? " every run made in the sandbox"
                : " made WITHOUT the sandbox")), printed);
    }

    @Test
    @Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void twoShardsMergedMakeTheSameReportAsOneGrading() throws Exception {
        Path subs = copySubmissions(List.of("alice", "bob", "erin", "frank", "heidi"));
        // A class refused at load: its report names the class file, under --out, which differs per shard.
        Path kim = Files.createDirectories(subs.resolve("kim"));
        Files.writeString(kim.resolve("Filer.java"), "import org.kheperasim.api.*;\n"
                + "public class Filer extends Controller {\n"
                + "    @Override protected void doWork() { new java.io.File(\"x\").delete(); sleepMillis(100); }\n}\n");
        String[] common = {"--submissions", subs.toString(), "--arenas", "maze", "lab", "--seeds", "1", "--seconds", "10",
            "--wall-limit", "90", "--heap-mb", "128"};
        Path whole = dir.resolve("whole");
        Path s1 = dir.resolve("shard1");
        Path s2 = dir.resolve("shard2");
        // The shards, as on two machines, each in a JVM of its own beside the whole grading (in this JVM).
        try (ChildGrading second = ChildGrading.start(dir.resolve("shard2.log"),
                ReportFolder.concat(common, "--shard", "2/2", "--out", s2.toString()));
                ChildGrading first = ChildGrading.start(dir.resolve("shard1.log"),
                        ReportFolder.concat(common, "--shard", "1/2", "--out", s1.toString()))) {
            grade(ReportFolder.concat(common, "--jobs", "2", "--out", whole.toString()));
            second.await(200);
            first.await(200);
        }
        Path merged = dir.resolve("merged");
        grade("merge", "--out", merged.toString(), s2.toString(), s1.toString());

        List<String> files = ReportFolder.files(whole);
        assertEquals(files, ReportFolder.files(merged));
        assertTrue(files.contains("img/alice__lab__s1.png") && files.contains("pages/alice__lab__s1.html"), files.toString());
        for (String f : files) {
            assertArrayEquals(Files.readAllBytes(whole.resolve(f)), Files.readAllBytes(merged.resolve(f)), f);
        }
        assertEquals(6, ReportFiles.read(s1.resolve("results.json")).runs().size());
        List<RunRecord> all = ReportFiles.read(merged.resolve("results.json")).runs();
        assertEquals(12, all.size());
        assertTrue(byStudent(all, "kim").detail().contains("uses java.io.File"), byStudent(all, "kim").detail());
    }

    private static RunRecord byStudent(List<RunRecord> runs, String student) {
        return runs.stream().filter(r -> r.student().equals(student)).findFirst().orElseThrow();
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

    /** Judy hands in compiled classes only, in a package folder. */
    private static void addClassSubmission(Path judy) throws IOException {
        Path src = judy.resolveSibling("judy-src").resolve("Cruiser.java");
        Files.createDirectories(src.getParent());
        Files.writeString(src, "package judy.bots;\nimport org.kheperasim.api.*;\npublic class Cruiser extends Controller {\n"
                + "    @Override protected void doWork() { setSpeeds(proximity(IrSensor.FRONT_LEFT) > 400 ? -3 : 4, 4);"
                + " sleepMillis(100); }\n}\n");
        Files.createDirectories(judy);
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp", System.getProperty("java.class.path"),
                "-d", judy.toString(), "--release", "17", src.toString()));
        Files.delete(src);
        Files.delete(src.getParent());
    }


    /** Grades in the sandbox where there is one (CI has it), else without it: the statuses are the same either way. */
    private static String grade(String... args) {
        boolean merge = args.length > 0 && args[0].equals("merge");
        boolean box = org.kheperasim.sim.sandbox.BoxProbe.unavailable().isEmpty();
        String[] full = Stream.concat(Stream.concat(Stream.of("grade"), Stream.of(args)),
                merge || box ? Stream.empty() : Stream.of("--no-sandbox")).toArray(String[]::new);
        PrintStream old = System.out;
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        int code;
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            code = Main.commandLine().execute(full);
        } finally {
            System.setOut(old);
        }
        String text = o.toString(StandardCharsets.UTF_8);
        assertEquals(0, code, text);
        return text;
    }
}
