package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The score is never the run's to write. Graded trusted (the hole a test build opens on purpose), in
 * the sandbox where there is one: a controller that prints a forged result line and halts its JVM
 * (the exploit that ranked first with 999 of 999 points), and one that moves its robot through every
 * cell of the maze by reflection (its run's own result says 100 points) are reported as tampered
 * and as differing from their replay (made again, the same again), and left out of the ranking, with
 * the points the grader's replay of their command logs gives; an honest student ranks first. Beside them, a thread pool that spins for ever costs its run
 * nothing: the child ends after its result, not at the wall limit.
 */
class ForgedResultsTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void forgersAreReportedAsTamperedWithTheReplaysScoreAndNotRanked() throws IOException {
        boolean box = org.kheperasim.sim.sandbox.BoxProbe.unavailable().isEmpty();
        if ("true".equals(System.getenv("CI"))) {
            Hostile.requireBox();
        }
        Path subs = dir.resolve("subs");
        Path bob = Files.createDirectories(subs.resolve("bob"));
        for (String f : List.of("Robot.java", "Turns.java")) {
            Files.copy(Path.of("src/test/resources/grade/bob", f), bob.resolve(f));
        }
        Hostile.printForger(subs.resolve("pat"));
        Hostile.memoryForger(subs.resolve("tom"));
        Hostile.poolSpinner(subs.resolve("paula"));
        Path out = dir.resolve("out");
        double wallLimit = 100;
        ReportFiles.Report report = Grader.grade(new Grader.Options(subs, List.of("maze"), 1, 2, out, GradePlan.Shard.ALL, 128,
                wallLimit, 5, 20.0, false, new PrintStream(OutputStream.nullOutputStream()), false, box, true));
        Map<String, RunRecord> runs = report.runs().stream().collect(Collectors.toMap(RunRecord::student, r -> r));
        String all = runs.toString();

        RunRecord pat = runs.get("pat");
        assertEquals(RunStatus.TAMPERED, pat.status(), all);
        assertEquals(0, pat.points(), "what it printed is no result: " + pat);
        assertTrue(pat.detail().contains("without handing over its command log"), pat.detail());

        RunRecord tom = runs.get("tom");
        // Its JVM ends normally with a result its replay never gives, in both makings of the run: named by what
        // differs and where (robot 0's end), scored by the replay, not ranked; not called tampered, which the
        // grader keeps for what the evidence shows (a result that is not the simulator's, an exit status it never gives).
        assertEquals(RunStatus.DIVERGED, tom.status(), all);
        assertTrue(tom.detail().contains("differs from the replay of its command log"), tom.detail());
        assertTrue(tom.detail().contains("in both makings") && tom.detail().contains("robot 0 ends with"), tom.detail());
        assertTrue(tom.madeAgain(), "made again once: " + tom);
        assertTrue(tom.points() < 10, "the score is the replay's (its robot never moved), not the 100 it claims: " + tom);
        assertFalse(tom.picture().isEmpty(), "its picture is the replay's");

        RunRecord honest = runs.get("bob");
        assertEquals(RunStatus.OK, honest.status(), all);

        RunRecord paula = runs.get("paula");
        assertEquals(20, paula.simulatedSeconds(), 1e-9, "the spinning pool's run went to its end: " + paula);
        assertFalse(paula.detail().contains("wall-clock"), paula.detail());
        String timings = Files.readString(out.resolve("timings.csv"));
        double paulaWall = Double.parseDouble(timings.lines().filter(l -> l.startsWith("paula")).findFirst().orElseThrow()
                .split(",")[2]);
        assertTrue(paulaWall < wallLimit / 2, "the child ended after its result, not at the wall limit: " + paulaWall + " s");

        String table = Files.readString(out.resolve("report.txt"));
        assertTrue(table.contains("   -  pat ") && table.contains("   -  tom "), "forgers are not ranked:\n" + table);
        String json = Files.readString(out.resolve("results.json"));
        String ranking = json.substring(json.indexOf("\"ranking\""));
        assertFalse(ranking.contains("\"pat\"") || ranking.contains("\"tom\""), ranking);
        assertTrue(ranking.contains("{\"rank\": 1, \"student\": \"bob\""), ranking);
    }
}
