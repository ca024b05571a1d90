package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.grade.platform.PlatformOptions;
import picocli.CommandLine;

/**
 * {@code grade --deadline}: a grading that cannot finish in its time stops at its deadline and writes
 * the runs finished before it with their points (a quick controller's), the others 0 saying why (one
 * that spins without end, with a hang timeout past the deadline), in the report and in Gradescope's
 * result; it writes no journal line for a run it stopped, so grading again makes it.
 */
class GradeDeadlineTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theRunsFinishedBeforeTheDeadlineKeepTheirPoints() throws Exception {
        Path subs = dir.resolve("subs");
        for (String f : List.of("alice/Explorer.java", "grace/Spinner.java")) {
            Path to = subs.resolve(f);
            Files.createDirectories(to.getParent());
            Files.copy(Path.of("src", "test", "resources", "grade", f), to);
        }
        Path out = dir.resolve("out");
        ByteArrayOutputStream progress = new ByteArrayOutputStream();
        long t0 = System.nanoTime();
        // One job: alice's runs (plan order) come first, then grace's run spins until the deadline stops it.
        double deadline = 20;
        ReportFiles.Report report = Grader.grade(new Grader.Options(subs, List.of("maze"), 2, 1, out, GradePlan.Shard.ALL,
                128, 300, 120, 2.0, false, new PrintStream(progress, true, StandardCharsets.UTF_8), false, false, false,
                Integer.MAX_VALUE, deadline));
        double took = (System.nanoTime() - t0) / 1e9;
        assertTrue(took < deadline + 20, "the grading ended " + took + " s after its start, its deadline " + deadline + " s");
        List<RunRecord> alice = report.runs().stream().filter(r -> r.student().equals("alice")).toList();
        List<RunRecord> grace = report.runs().stream().filter(r -> r.student().equals("grace")).toList();
        for (RunRecord r : alice) {
            assertEquals(RunStatus.OK, r.status(), r + "\n" + progress.toString(StandardCharsets.UTF_8));
            assertTrue(r.points() > 0, r.toString());
        }
        for (RunRecord r : grace) {
            assertTrue(GradeDeadline.notMade(r), r.toString());
            assertEquals(0, r.points());
            assertEquals(100, r.max());
            assertTrue(r.detail().startsWith("not made: the grading's deadline (--deadline 20 s) passed first"), r.detail());
        }
        assertTrue(progress.toString(StandardCharsets.UTF_8).contains("the grading's deadline (--deadline 20 s) passed"));
        assertEquals(2, Files.readAllLines(out.resolve("journal.jsonl")).stream().filter(l -> l.contains("\"alice\"")).count());
        assertTrue(Files.readAllLines(out.resolve("journal.jsonl")).stream().noneMatch(l -> l.contains("\"grace\"")),
                "a run the deadline stopped goes to no journal");

        PlatformOptions platforms = new PlatformOptions();
        new CommandLine(platforms).parseArgs("--format", "gradescope");
        platforms.write(report, out, StrictMath.round(took));
        @SuppressWarnings("unchecked")
        Map<String, Object> a = (Map<String, Object>) JsonValues.parse(Files.readString(out.resolve("gradescope/alice/results.json")));
        assertEquals(alice.stream().mapToDouble(RunRecord::points).sum(), ((Number) a.get("score")).doubleValue(), 0.011);
        @SuppressWarnings("unchecked")
        Map<String, Object> g = (Map<String, Object>) JsonValues.parse(Files.readString(out.resolve("gradescope/grace/results.json")));
        assertEquals(0.0, ((Number) g.get("score")).doubleValue());
        assertTrue(((String) g.get("output")).contains("the grading's deadline passed before 2 of the 2 runs"), g.toString());
        assertEquals(Set.of(true), Set.of(g.get("extra_data")).stream().map(x -> ((Map<?, ?>) x).get("gradable")).collect(
                java.util.stream.Collectors.toSet()));
    }
}
