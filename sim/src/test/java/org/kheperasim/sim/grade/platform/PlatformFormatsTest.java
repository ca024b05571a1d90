package org.kheperasim.sim.grade.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.grade.GradeDeadline;
import org.kheperasim.sim.grade.GradePlan;
import org.kheperasim.sim.grade.JsonValues;
import org.kheperasim.sim.grade.ReportFiles;
import org.kheperasim.sim.grade.RunRecord;
import org.kheperasim.sim.grade.RunStatus;

/**
 * Each platform's file, field by field against the platform's own published example and specification
 * (test resources {@code platforms/}, each naming its source): no field the platform does not define,
 * each of the type the platform's example gives it, each value in the platform's value set; and what the
 * file says: a test per run with its points, the student's file and line of a failure, hidden arenas
 * hidden, a run past the deadline 0 beside the others' points, a submission that does not compile not
 * gradable (apart from a zero), a hostile name escaped. One made-up report (no JVM), shared.
 */
class PlatformFormatsTest {
    private static final String ESC_NAME = "\u001b[31mcat";
    private static final Set<String> VISIBILITIES = Set.of("hidden", "after_due_date", "after_published", "visible");

    @TempDir
    static Path dir;
    private static List<PlatformResult> results;

    @BeforeAll
    static void grade() throws IOException {
        GradePlan plan = new GradePlan(List.of("amy", "bob", ESC_NAME), List.of("maze", "two-rooms"), 2);
        List<RunRecord> runs = new ArrayList<>();
        runs.add(ok("amy", "maze", 1, 72));
        runs.add(new RunRecord("amy", "maze", 2, RunStatus.THREW, 16, 100, 16, 4.2, "Thrower", "java.lang"
                + ".ArrayIndexOutOfBoundsException: Index 10 out of bounds for length 10 at Thrower.doWork(Thrower.java:9) |"
                + " visit c*: 4/25 regions", picture("amy__maze__s2"), RunRecord.NO_SANDBOX));
        runs.add(ok("amy", "two-rooms", 1, 50));
        runs.add(new RunRecord("amy", "two-rooms", 2, RunStatus.ERROR, 0, 100, 0, 0, "", GradeDeadline.NOT_MADE
                + " (--deadline 45 s) passed first; it counts 0 here", "", ""));
        for (String a : plan.arenas()) {
            for (int s = 1; s <= 2; s++) {
                runs.add(new RunRecord("bob", a, s, RunStatus.COMPILE_FAILED, 0, 100, 0, 0, "", "Broken.java:7:24: error: ';'"
                        + " expected", "", ""));
            }
        }
        for (String a : plan.arenas()) {
            for (int s = 1; s <= 2; s++) {
                runs.add(new RunRecord(ESC_NAME, a, s, RunStatus.TAMPERED, 3, 100, 3, 60, "Forger\u0007", "a result line"
                        + " \u001b]0;owned\u0007 that is not the simulator's JSON", "", RunRecord.NO_SANDBOX));
            }
        }
        ReportFiles.Report report = new ReportFiles.Report(plan, GradePlan.Shard.ALL, runs);
        results = GradingTests.of(report, Set.of("two-rooms"));
        PlatformFormat.writeAll(results, Set.of(PlatformFormat.values()), dir, 12);
    }

    private static RunRecord ok(String student, String arena, long seed, double points) throws IOException {
        return new RunRecord(student, arena, seed, RunStatus.OK, points, 100, points, 60, "Explorer", "visit c*: 18/25 regions",
                picture(student + "__" + arena + "__s" + seed), RunRecord.NO_SANDBOX);
    }

    private static String picture(String id) throws IOException {
        String rel = "img/" + id + ".png";
        Files.createDirectories(dir.resolve("img"));
        BufferedImage img = new BufferedImage(32, 24, BufferedImage.TYPE_INT_RGB);
        img.setRGB(3, 4, 0x1f5fbf);
        ImageIO.write(img, "png", dir.resolve(rel).toFile());
        return rel;
    }

    private static String file(PlatformFormat f, String student) throws IOException {
        return Files.readString(dir.resolve(f.word()).resolve(PlatformFormat.folder(student)).resolve(f.file()));
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> json(PlatformFormat f, String student) throws IOException {
        return (Map<String, Object>) JsonValues.parse(file(f, student));
    }

    @SuppressWarnings("unchecked")
    private static List<Map<String, Object>> tests(Map<String, Object> m) {
        return (List<Map<String, Object>>) m.get("tests");
    }

    private static double num(Object o) {
        return ((Number) o).doubleValue();
    }

    @Test
    void gradescopeFieldByFieldAsItsSpecification() throws IOException {
        Map<String, java.util.Set<String>> published = PublishedShapes.shape(PublishedShapes.example("gradescope-specs-example.jsonc"));
        for (String s : List.of("amy", "bob", ESC_NAME)) {
            Map<String, Object> m = json(PlatformFormat.GRADESCOPE, s);
            assertEquals(List.of(), PublishedShapes.differences(PublishedShapes.shape(m), published, Set.of("extra_data",
                    "tests[].extra_data")), s);
            assertTrue(VISIBILITIES.contains(m.get("visibility")) && VISIBILITIES.contains(m.get("stdout_visibility")), s);
            for (Map<String, Object> t : tests(m)) {
                assertTrue(VISIBILITIES.contains(t.get("visibility")), t.toString());
                assertTrue(num(t.get("score")) <= num(t.get("max_score")), t.toString());
            }
            assertEquals(12, num(m.get("execution_time")));
        }
        Map<String, Object> amy = json(PlatformFormat.GRADESCOPE, "amy");
        assertEquals(138, num(amy.get("score")), "partial credit: 72 + 16 + 50, and 0 for the run past the deadline");
        List<Map<String, Object>> t = tests(amy);
        assertEquals(List.of("maze, seed 1", "maze, seed 2", "two-rooms, seed 1", "two-rooms, seed 2"),
                t.stream().map(x -> x.get("name")).toList());
        assertEquals(List.of("1.1", "1.2", "2.1", "2.2"), t.stream().map(x -> x.get("number")).toList());
        assertEquals(List.of("visible", "visible", "hidden", "hidden"), t.stream().map(x -> x.get("visibility")).toList());
        assertEquals(List.of(72.0, 16.0, 50.0, 0.0), t.stream().map(x -> num(x.get("score"))).toList());
        assertTrue(((String) t.get(1).get("output")).contains("threw") && ((String) t.get(1).get("output"))
                .contains("at Thrower.doWork(Thrower.java:9)"), "the failure with the student's file and line");
        assertTrue(((String) t.get(3).get("output")).contains("deadline"));
        assertTrue(((String) amy.get("output")).contains("deadline passed before 1 of the 4 runs"));
        assertEquals(List.of(Map.of("name", "maze mean %", "value", 44.0, "order", "desc")), amy.get("leaderboard"),
                "a leaderboard of the visible arenas only");

        Map<String, Object> bob = json(PlatformFormat.GRADESCOPE, "bob");
        assertEquals(Map.of("gradable", false), bob.get("extra_data"));
        assertEquals(0, num(bob.get("score")));
        assertEquals(1, tests(bob).size());
        assertEquals(400, num(tests(bob).get(0).get("max_score")));
        assertTrue(((String) tests(bob).get(0).get("output")).contains("not gradable: failed to compile: Broken.java:7:24"));
        assertEquals(List.of(), bob.get("leaderboard"));
    }

    @Test
    void prairieLearnFieldByFieldAsItsExternalGradingSpecification() throws IOException {
        Map<String, java.util.Set<String>> published = new java.util.TreeMap<>(PublishedShapes.shape(
                PublishedShapes.example("prairielearn-results-example.jsonc")));
        // "format_errors": "either a string or an array of strings" (the same section, not in its example)
        published.put("format_errors", Set.of("string", "array"));
        published.put("format_errors[]", Set.of("string"));
        for (String s : List.of("amy", "bob", ESC_NAME)) {
            Map<String, Object> m = json(PlatformFormat.PRAIRIELEARN, s);
            assertEquals(List.of(), PublishedShapes.differences(PublishedShapes.shape(m), published, Set.of()), s);
            if (Boolean.TRUE.equals(m.get("gradable"))) {
                assertTrue(num(m.get("score")) >= 0 && num(m.get("score")) <= 1, s);
            }
        }
        Map<String, Object> amy = json(PlatformFormat.PRAIRIELEARN, "amy");
        assertEquals(0.35, num(amy.get("score")), 0.005, "138 of 400 points");
        List<Map<String, Object>> t = tests(amy);
        assertEquals(List.of(72.0, 16.0, 50.0, 0.0), t.stream().map(x -> num(x.get("points"))).toList());
        assertEquals(List.of(100.0, 100.0, 100.0, 100.0), t.stream().map(x -> num(x.get("max_points"))).toList());
        assertTrue(((String) t.get(1).get("output")).contains("Thrower.java:9"));
        assertEquals("hidden test 2.1", t.get(2).get("name"), "no visibility in PrairieLearn: a hidden arena keeps its points only");
        assertFalse(file(PlatformFormat.PRAIRIELEARN, "amy").contains("two-rooms"));
        @SuppressWarnings("unchecked")
        List<Map<String, Object>> images = (List<Map<String, Object>>) t.get(0).get("images");
        String url = (String) images.get(0).get("url");
        assertTrue(url.startsWith("data:image/png;base64,"), url);
        assertEquals(List.of(Files.readAllBytes(dir.resolve("img/amy__maze__s1.png")).length),
                List.of(Base64.getDecoder().decode(url.substring(url.indexOf(',') + 1)).length));
        assertEquals(null, t.get(2).get("images"), "a hidden run's picture is not shown");

        Map<String, Object> bob = json(PlatformFormat.PRAIRIELEARN, "bob");
        assertEquals(false, bob.get("gradable"), "not gradable: no attempt used, no points, apart from a zero");
        assertFalse(bob.containsKey("score"));
        assertTrue(((List<?>) bob.get("format_errors")).get(0).toString().contains("Broken.java:7:24: error: ';' expected"));
    }

    @Test
    void prairieLearnKeepsWithinItsMegabyte(@TempDir Path big) throws IOException {
        Random random = new Random(7);
        List<PlatformTest> tests = new ArrayList<>();
        Files.createDirectories(big.resolve("img"));
        for (int i = 1; i <= 30; i++) {
            BufferedImage img = new BufferedImage(160, 120, BufferedImage.TYPE_INT_RGB);
            for (int y = 0; y < 120; y++) {
                for (int x = 0; x < 160; x++) {
                    img.setRGB(x, y, random.nextInt());
                }
            }
            ImageIO.write(img, "png", big.resolve("img/r" + i + ".png").toFile());
            tests.add(new PlatformTest("maze, seed " + i, "1." + i, 10, 10, true, "ok", "ok", false, "img/r" + i + ".png", "maze"));
        }
        String text = PrairieLearnFormat.of(new PlatformResult("amy", tests, true, "", List.of(), "amy: 300 of 300"), big);
        int bytes = text.getBytes(StandardCharsets.UTF_8).length;
        assertTrue(bytes <= 1_000_000, bytes + " bytes");
        assertTrue(bytes > 700_000, "as many pictures as fit: " + bytes);
        assertTrue(text.contains("trajectory pictures left out to keep the result within PrairieLearn's 1 MB"));
    }

    @Test
    @SuppressWarnings("unchecked")
    void classroomAsItsReporterReadsIt() throws IOException {
        Map<String, java.util.Set<String>> published = new java.util.TreeMap<>(PublishedShapes.shape(
                PublishedShapes.example("classroom-runner-example.jsonc")));
        published.get("tests[].message").add("null"); // the reporter's own test passes null
        for (String s : List.of("amy", "bob", ESC_NAME)) {
            Map<String, Object> m = json(PlatformFormat.CLASSROOM, s);
            assertEquals(List.of(), PublishedShapes.differences(PublishedShapes.shape(m), published, Set.of()), s);
            assertTrue(Set.of("pass", "fail", "error").contains(m.get("status")), s);
            assertEquals(1, num(m.get("version")));
            for (Map<String, Object> t : tests(m)) {
                assertTrue(Set.of("pass", "fail", "error").contains(t.get("status")), t.toString());
            }
        }
        // What the reporter does (notify-classroom.js): the runner's result, base64, decoded; tests[].score summed.
        String b64 = Base64.getEncoder().encodeToString(file(PlatformFormat.CLASSROOM, "amy").getBytes(StandardCharsets.UTF_8));
        Map<String, Object> amy = (Map<String, Object>) JsonValues.parse(new String(Base64.getDecoder().decode(b64),
                StandardCharsets.UTF_8));
        assertEquals(138, tests(amy).stream().mapToDouble(t -> num(t.get("score"))).sum(), "partial credit per run");
        assertEquals(400, num(amy.get("max_score")));
        assertEquals("error", amy.get("status"), "a run not made (the deadline) is an error");
        assertEquals("Thrower.java", tests(amy).get(1).get("filename"));
        assertEquals(9, num(tests(amy).get(1).get("line_no")));
        assertEquals("fail", tests(amy).get(1).get("status"));
        assertEquals("hidden test 2.1", tests(amy).get(2).get("name"));
        Map<String, Object> bob = json(PlatformFormat.CLASSROOM, "bob");
        assertEquals("error", bob.get("status"));
        assertTrue(((String) tests(bob).get(0).get("message")).contains("not gradable"));
    }

    @Test
    @SuppressWarnings("unchecked")
    void codeGradeEndsWithItsPointsLine() throws IOException {
        String published;
        try (var in = getClass().getResourceAsStream("/platforms/codegrade-points-example.txt")) {
            published = new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().filter(l -> !l.startsWith("#"))
                    .findFirst().orElseThrow();
        }
        Map<String, Object> example = (Map<String, Object>) JsonValues.parse(published);
        for (String s : List.of("amy", "bob", ESC_NAME)) {
            List<String> lines = file(PlatformFormat.CODEGRADE, s).lines().toList();
            Map<String, Object> last = (Map<String, Object>) JsonValues.parse(lines.get(lines.size() - 1));
            assertEquals(example.keySet(), last.keySet());
            assertEquals(example.get("tag"), last.get("tag"));
            assertTrue(((String) last.get("points")).matches("\\d+(\\.\\d{1,2})?/\\d+(\\.\\d{1,2})?"), last.toString());
        }
        List<String> amy = file(PlatformFormat.CODEGRADE, "amy").lines().toList();
        assertEquals("{\"tag\": \"points\", \"points\": \"138/400\"}", amy.get(amy.size() - 1));
        assertTrue(amy.stream().anyMatch(l -> l.startsWith("[FAIL] maze, seed 2") && l.contains("Thrower.java:9")));
        assertFalse(file(PlatformFormat.CODEGRADE, "amy").contains("two-rooms"));
        List<String> bob = file(PlatformFormat.CODEGRADE, "bob").lines().toList();
        assertEquals("{\"tag\": \"points\", \"points\": \"0/400\"}", bob.get(bob.size() - 1));
        assertTrue(bob.get(0).startsWith("not gradable: failed to compile: Broken.java:7:24"));
    }

    @Test
    void studentTextIsShownEscaped() throws IOException {
        for (PlatformFormat f : PlatformFormat.values()) {
            String text = file(f, ESC_NAME);
            assertFalse(text.chars().anyMatch(c -> c == 0x1b || c == 0x07), f + ": a raw control character");
            assertTrue(text.contains("\\\\e]0;owned") || text.contains("\\e]0;owned"), f + ": " + text);
        }
        assertEquals("__31mcat", PlatformFormat.folder(ESC_NAME), "a folder name of safe characters");
    }

    @Test
    void aFormatThatIsNoneIsRefusedNamingThem() {
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> PlatformFormat.parse(List.of("gradescope,moodle")));
        assertEquals("--format moodle: not a platform; give one or more of gradescope, prairielearn, classroom, codegrade,"
                + " e.g. --format gradescope,prairielearn", e.getMessage());
        assertEquals(List.of(PlatformFormat.GRADESCOPE, PlatformFormat.CODEGRADE), List.copyOf(PlatformFormat.parse(
                List.of("gradescope, codegrade", "gradescope"))));
        assertEquals(540.0, GradeDeadline.parse("9m"));
        assertEquals(45.0, GradeDeadline.parse("45"));
        assertEquals(0.8, GradeDeadline.parse("800ms"));
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> GradeDeadline.parse("soon"));
    }
}
