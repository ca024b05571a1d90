package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.task.Score;

/**
 * The report as an instructor sends it back, from runs made up here (no child JVM: quick): a run that
 * threw names the student's line in every format, a hang's message keeps its useful part without the
 * machine's seconds, each seed shows its score and, when not ok, its status, a failure never ties a
 * clean run, and an empty hand-in folder is "nothing handed in".
 */
class GradeReportTest {
    private static final GradePlan PLAN = new GradePlan(List.of("amy", "ben", "cat", "dan"), List.of("maze"), 5);
    private static final String TRACE = "java.lang.ArrayIndexOutOfBoundsException: Index 10 out of bounds for length 10\n"
            + "threw java.lang.ArrayIndexOutOfBoundsException: Index 10 out of bounds for length 10; the robot was stopped.\n"
            + "java.lang.ArrayIndexOutOfBoundsException: Index 10 out of bounds for length 10\n"
            + "\tat java.base/java.util.Arrays.fill(Arrays.java:3287)\n"
            + "\tat org.kheperasim.api.Controller.helper(Controller.java:80)\n"
            + "\tat Thrower.doWork(Thrower.java:9)\n"
            + "\tat org.kheperasim.api.Controller.run(Controller.java:64)\n";

    @TempDir
    Path dir;

    @Test
    void theStudentsLineIsTheFirstFrameOfTheirCode() {
        assertEquals("Thrower.doWork(Thrower.java:9)", FailureText.studentFrame(TRACE));
        assertEquals("my.pkg.Bot$Inner.lambda$step$0(Bot.java:41)", FailureText.studentFrame(
                "threw x\n\tat app//my.pkg.Bot$Inner.lambda$step$0(Bot.java:41)\n"));
        assertEquals(null, FailureText.studentFrame("threw x\n\tat java.base/java.lang.Thread.run(Thread.java:840)\n"));
    }

    @Test
    void aRunThatThrewNamesTheStudentsLineInEveryFormat() throws IOException {
        Map<String, Object> claim = Map.of("robots", List.of(Map.<String, Object>of("controllerStatus", "failed", "failure",
                "java.lang.ArrayIndexOutOfBoundsException: Index 10 out of bounds for length 10", "failureAt",
                "Thrower.doWork(Thrower.java:9)", "failureSeconds", 2.0)));
        RunRecord threw = ChildResults.fromClaim(PLAN.jobs().get(0), "Thrower", claim, score(4), 2.001, "", RunRecord.SANDBOX);
        assertEquals("java.lang.ArrayIndexOutOfBoundsException: Index 10 out of bounds for length 10 at"
                + " Thrower.doWork(Thrower.java:9) | visit c*: 1/25 regions", threw.detail());

        String longMessage = "java.lang.IllegalStateException: " + "x".repeat(400);
        RunRecord cut = ChildResults.fromClaim(PLAN.jobs().get(0), "Thrower", Map.of("robots", List.of(Map.of(
                "controllerStatus", "failed", "failure", longMessage, "failureAt", "Thrower.doWork(Thrower.java:9)"))),
                null, 2, "", RunRecord.SANDBOX);
        assertTrue(cut.detail().endsWith("... at Thrower.doWork(Thrower.java:9)"), "a long message is cut, never the line: "
                + cut.detail());

        ReportFiles.write(report(List.of(threw)), dir);
        for (String file : new String[] {"results.csv", "results.json", "report.txt", "index.html"}) {
            assertTrue(Files.readString(dir.resolve(file)).contains("at Thrower.doWork(Thrower.java:9)"), file);
        }
    }

    @Test
    void aHangKeepsItsUsefulPartWithoutTheMachinesSeconds() {
        String err = "[    1.000 s] ERROR Spinner: controller Spinner (Spinner) stopped making API calls at simulated time"
                + " 1.000 s: it ran for 5.3 s of real time without reading a sensor, setting a motor or sleeping. A loop that"
                + " waits for something must read a sensor or call Thread.sleep inside it. The controller was stopped and the"
                + " robot's motors set to 0.\n";
        Map<String, Object> claim = Map.of("robots", List.of(Map.of("controllerStatus", "hung", "failure", "later")));
        RunRecord hung = ChildResults.fromClaim(PLAN.jobs().get(0), "Spinner", claim, null, 1, err, RunRecord.SANDBOX);
        assertEquals("controller Spinner (Spinner) stopped making API calls at simulated time 1.000 s: it ran for longer"
                + " than the hang timeout without reading a sensor, setting a motor or sleeping. A loop that waits for"
                + " something must read a sensor or call Thread.sleep inside it.", hung.detail());
        RunRecord fromClaim = ChildResults.fromClaim(PLAN.jobs().get(0), "Empty", Map.of("robots", List.of(Map.of(
                "controllerStatus", "hung", "failure", "controller Empty (Empty) stopped making API calls at simulated time"
                        + " 0.000 s: its doWork() returns at once (an empty doWork() does this; it went on for 2.0 s of real"
                        + " time). Give doWork() its work. The controller was stopped and the robot's motors set to 0."))),
                null, 0, "", RunRecord.SANDBOX);
        assertEquals("controller Empty (Empty) stopped making API calls at simulated time 0.000 s: its doWork() returns at"
                + " once (an empty doWork() does this; it went on for longer than the hang timeout). Give doWork() its work.",
                fromClaim.detail(), "without an error line, the run's own text, cleaned the same way");
        RunRecord refused = ChildResults.noResult(PLAN.jobs().get(0), "Filer", false, 60, 2, "khepera-sim: error: controller"
                + " Filer was refused: Cannot load class Filer from /tmp/x/Filer.class: Filer.java:3: uses java.io.File:"
                + " controllers may not touch files\n", RunRecord.SANDBOX);
        assertEquals("controller Filer was refused at load: Filer.java:3: uses java.io.File: controllers may not touch files",
                refused.detail());
    }

    @Test
    void eachSeedShowsItsScoreAndAFailureNeverTiesACleanRun() throws IOException {
        double[] amy = {16, 28, 16, 20, 16};
        List<RunRecord> runs = new java.util.ArrayList<>();
        for (int s = 1; s <= 5; s++) {
            runs.add(run("amy", s, RunStatus.OK, amy[s - 1]));
            runs.add(run("ben", s, RunStatus.OK, 0));
            runs.add(run("cat", s, s == 2 ? RunStatus.THREW : RunStatus.OK, 0));
            runs.add(run("dan", s, RunStatus.HUNG, 0));
        }
        ReportFiles.write(report(runs), dir);
        String text = Files.readString(dir.resolve("report.txt"));
        assertTrue(text.contains("   1  amy         19.2     19.2  16 | 28 | 16 | 20 | 16\n"), text);
        assertTrue(text.contains("   2  ben            0        0  0 | 0 | 0 | 0 | 0\n"), "a clean 0 ranks before a failed 0:\n" + text);
        assertTrue(text.contains("   3  cat            0        0  0 | 0 (threw) | 0 | 0 | 0\n"), text);
        assertTrue(text.contains("   4  dan            0        0  0 (hung) | 0 (hung) | 0 (hung) | 0 (hung) | 0 (hung)\n"), text);
        assertTrue(text.contains(Ranking.RULE), text);
        String html = Files.readString(dir.resolve("index.html"));
        assertTrue(html.contains(">16</span> | <span class=\"ok\" title=\"seed 2\">28</span> | "), html);
        assertTrue(html.contains("<span class=\"bad\" title=\"seed 2: what went wrong\">0 (threw)</span>"), html);
        assertTrue(html.contains("fewer runs not ok rank first"), html);
        assertFalse(html.contains("<td>1</td><td>ben</td>"), html);
    }

    @Test
    void anEmptyFolderIsNothingHandedIn() throws IOException {
        Path empty = Files.createDirectories(dir.resolve("subs/zed"));
        Files.writeString(empty.resolve(".DS_Store"), "");
        Submission none = Submissions.prepare(empty, dir.resolve("work/zed"));
        assertTrue(none.empty() && !none.runnable(), none.toString());
        assertEquals("the folder is empty", none.problem());
        Path zipped = Files.createDirectories(dir.resolve("subs/yan"));
        Files.writeString(zipped.resolve("robot.zip"), "PK");
        assertEquals("no .java or .class file; the folder holds 1 file: robot.zip",
                Submissions.prepare(zipped, dir.resolve("work/yan")).problem());
        assertEquals("nothing handed in", RunStatus.NOTHING_HANDED_IN.label());
        assertEquals("nothing_handed_in", RunStatus.NOTHING_HANDED_IN.word());
    }

    private static RunRecord run(String student, long seed, RunStatus status, double points) {
        return new RunRecord(student, "maze", seed, status, points, 100, points, status == RunStatus.OK ? 600 : 3, "Bot",
                status == RunStatus.OK ? "" : "what went wrong", "", RunRecord.SANDBOX);
    }

    private static ReportFiles.Report report(List<RunRecord> runs) {
        return new ReportFiles.Report(PLAN, GradePlan.Shard.ALL, runs);
    }

    private static Score score(double points) {
        return new Score(List.of(new Score.Part("task visit c*", points / 100, points, 100, "1/25 regions")), points, 100);
    }
}
