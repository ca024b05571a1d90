package org.kheperasim.sim.grade.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.grade.JsonValues;

/**
 * The ready Gradescope folder ({@code docs/examples/gradescope}) as Gradescope runs it: its
 * {@code run_autograder}, unchanged, under a root laid out as Gradescope lays out {@code /autograder}
 * ({@code source/} with the zip's files, {@code submission/} with the student's, {@code results/}),
 * with its {@code grade.conf} cut to 2 seeds of 3 simulated seconds. A working controller gets a test per
 * arena and seed, each with its own points (partial credit, never all or nothing), the hidden arena's
 * hidden; one that does not compile is reported not gradable with the compiler's line.
 */
class GradescopeAutograderTest {
    private static final Path READY = Path.of("..", "docs", "examples", "gradescope");

    @TempDir
    static Path dir;

    @BeforeAll
    static void needsBash() {
        if (!Files.isExecutable(Path.of("/bin/bash"))) {
            if ("true".equals(System.getenv("CI"))) {
                fail("no /bin/bash; CI=true requires the Gradescope autograder test to run");
            }
            Assumptions.assumeTrue(false, "no /bin/bash: the Gradescope autograder test is skipped");
        }
    }

    /** Lays out a root as Gradescope does, runs run_autograder there, and returns its results.json. */
    @SuppressWarnings("unchecked")
    private static Map<String, Object> autograde(String name, String... files) throws IOException, InterruptedException {
        Path root = Files.createDirectories(dir.resolve(name));
        Path source = Files.createDirectories(root.resolve("source"));
        Files.copy(READY.resolve("run_autograder"), source.resolve("run_autograder"));
        String conf = Files.readString(READY.resolve("grade.conf")).replace("SEEDS=10", "SEEDS=2")
                .replace("SECONDS_PER_RUN=60", "SECONDS_PER_RUN=3");
        assertTrue(conf.contains("SEEDS=2") && conf.contains("SECONDS_PER_RUN=3") && conf.contains("HIDDEN=\"two-rooms\""), conf);
        Files.writeString(source.resolve("grade.conf"), conf);
        Path submission = Files.createDirectories(root.resolve("submission"));
        for (String f : files) {
            Path from = Path.of("src", "test", "resources", "grade").resolve(f);
            Files.copy(from, submission.resolve(from.getFileName()));
        }
        ProcessBuilder pb = new ProcessBuilder("/bin/bash", source.resolve("run_autograder").toString()).directory(root.toFile())
                .redirectErrorStream(true).redirectOutput(root.resolve("stdout").toFile());
        pb.environment().put("AUTOGRADER_ROOT", root.toAbsolutePath().toString());
        pb.environment().put("KSIM_CLASSPATH", System.getProperty("java.class.path"));
        pb.environment().put("JAVA", Path.of(System.getProperty("java.home"), "bin", "java").toString());
        Process p = pb.start();
        if (!p.waitFor(150, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            fail("run_autograder did not end in 150 s: " + Files.readString(root.resolve("stdout")));
        }
        String stdout = Files.readString(root.resolve("stdout"), StandardCharsets.UTF_8);
        Path results = root.resolve("results").resolve("results.json");
        assertTrue(Files.isRegularFile(results), "no results.json: " + stdout);
        return (Map<String, Object>) JsonValues.parse(Files.readString(results));
    }

    @SuppressWarnings("unchecked")
    private static List<Map<String, Object>> tests(Map<String, Object> m) {
        return (List<Map<String, Object>>) m.get("tests");
    }

    private static double num(Object o) {
        return ((Number) o).doubleValue();
    }

    @Test
    @Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aWorkingControllerGetsPartialCreditPerRunAndANotCompilingOneIsReportedSo() throws Exception {
        Map<String, Object> r = autograde("explorer", "alice/Explorer.java");
        List<Map<String, Object>> t = tests(r);
        assertEquals(List.of("maze, seed 1", "maze, seed 2", "two-rooms, seed 1", "two-rooms, seed 2"),
                t.stream().map(x -> x.get("name")).toList(), r.toString());
        assertEquals(List.of("visible", "visible", "hidden", "hidden"), t.stream().map(x -> x.get("visibility")).toList());
        double sum = 0;
        boolean partial = false;
        for (Map<String, Object> x : t) {
            double s = num(x.get("score"));
            double max = num(x.get("max_score"));
            assertTrue(s >= 0 && s <= max && max > 0, x.toString());
            assertTrue(((String) x.get("output")).startsWith("ok: "), x.toString());
            partial |= s > 0 && s < max;
            sum += s;
        }
        assertTrue(partial, "each run its own share of its points, not all or nothing: " + t);
        assertEquals(sum, num(r.get("score")), 0.011);
        assertEquals(Map.of("gradable", true), r.get("extra_data"));
        assertEquals(List.of("maze mean %"), ((List<Map<String, Object>>) (List<?>) r.get("leaderboard")).stream()
                .map(x -> x.get("name")).toList(), "no leaderboard column of the hidden arena");

        Map<String, Object> broken = autograde("broken", "erin/Broken.java");
        assertEquals(Map.of("gradable", false), broken.get("extra_data"));
        assertEquals(0, num(broken.get("score")));
        String output = (String) tests(broken).get(0).get("output");
        assertTrue(output.startsWith("not gradable: failed to compile: Broken.java:7:"), output);
        assertEquals("visible", tests(broken).get(0).get("visibility"));
    }
}
