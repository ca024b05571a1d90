package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.commandlog.CommandLogWriter;
import org.kheperasim.sim.commandlog.LogHeader;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;

/**
 * The grader's guard against calling an honest student a cheat: a run whose JVM ended normally and
 * whose result differs from its replay is made again once, and only a difference that repeats is
 * named (differs from its replay, with what and where); a difference from a JVM that ended with an
 * exit status the simulator never gives is tampering. The report counts the reruns and says what
 * differed the first time, in report.txt, results.json and results.csv alike.
 */
class RerunTest {
    private static final GradePlan PLAN = new GradePlan(List.of("amy"), List.of("lab"), 1);
    private static final GradePlan.Job JOB = PLAN.jobs().get(0);

    @TempDir
    Path dir;

    @Test
    void aDifferenceThatDoesNotRepeatIsMadeAgainAndCounted() throws IOException {
        AtomicInteger makings = new AtomicInteger();
        ChildRun.Outcome first = outcome(RunStatus.DIVERGED, "its own result differs (its trace's SHA-256 ...)");
        ChildRun.Outcome made = Rerun.guard(first, () -> {
            makings.incrementAndGet();
            return outcome(RunStatus.OK, null);
        });
        assertEquals(1, makings.get(), "made again once");
        assertEquals(RunStatus.OK, made.record().status());
        assertTrue(made.record().madeAgain());
        assertEquals("its own result differs (its trace's SHA-256 ...)", made.record().rerun());

        ChildRun.Outcome clean = outcome(RunStatus.OK, null);
        assertEquals(clean, Rerun.guard(clean, () -> {
            throw new AssertionError("a run that did not differ is made once");
        }));

        ChildRun.Outcome twice = Rerun.guard(first, () -> outcome(RunStatus.DIVERGED, "its own result differs again"));
        assertEquals(RunStatus.DIVERGED, twice.record().status());
        assertTrue(twice.record().detail().startsWith("in both makings of the run: "), twice.record().detail());

        RunRecord plain = outcome(RunStatus.OK, null).record();
        ReportFiles.write(new ReportFiles.Report(PLAN, GradePlan.Shard.ALL, List.of(made.record())), dir);
        String table = Files.readString(dir.resolve("report.txt"));
        assertTrue(table.contains("; 1 rerun (a result that differed from its replay, made again once)"), table);
        assertTrue(table.contains("made again: amy, lab, seed 1: the first time its own result differs"), table);
        assertEquals(made.record(), ReportFiles.read(dir.resolve("results.json")).runs().get(0), "results.json keeps it");
        assertEquals(made.record(), ReportFiles.readCsv(dir.resolve("results.csv")).get(0), "results.csv keeps it");
        assertTrue(Files.readString(dir.resolve("results.csv")).lines().findFirst().orElseThrow().endsWith(",rerun"));
        ReportFiles.write(new ReportFiles.Report(PLAN, GradePlan.Shard.ALL, List.of(plain)), dir);
        assertTrue(Files.readString(dir.resolve("report.txt")).contains("; 0 reruns"));
    }

    @Test
    void theVerdictNamesWhatDiffersAndWhereAndKeepsTamperingForEvidence() throws IOException {
        Path log = dir.resolve("run.log.gz");
        RunResult run = record(log, null);
        // An honest claim: the run's own result, as the simulator writes it.
        Verdict.Judged honest = judge(log, 0);
        assertEquals(RunStatus.OK, honest.record().status(), honest.record().toString());
        assertNull(honest.diverged());

        record(log, String.format(Locale.ROOT, "%.4f", run.first().x() + 3));
        Verdict.Judged once = judge(log, 0);
        assertEquals(RunStatus.DIVERGED, once.record().status(), once.record().toString());
        assertNotNull(once.diverged(), "to be made again");
        assertTrue(once.record().detail().contains("robot 0 ends with x "), "where: " + once.record().detail());

        Verdict.Judged odd = judge(log, 7);
        assertEquals(RunStatus.TAMPERED, odd.record().status(), odd.record().toString());
        assertNull(odd.diverged(), "evidence, not made again");
        assertTrue(odd.record().detail().contains("exit status 7, which the simulator never gives"), odd.record().detail());
        assertFalse(Ranking.of(List.of(once.record())).get("lab").get(0).ranked(), "not ranked until a person has looked");
    }

    private Verdict.Judged judge(Path log, int exit) {
        Submission sub = new Submission("amy", dir, "Braitenberg", null, false);
        ChildRun.Limits lim = new ChildRun.Limits(128, 60, 5, 5.0, Grader.SAMPLE_MILLIS, 1, false, true);
        return Verdict.judge(JOB, sub, ArenaFormat.resolve("lab"), lim,
                new Verdict.Child(false, exit, "", log, false, RunRecord.NO_SANDBOX), dir.resolve("replay.trace"));
    }

    /** Records a graded-style run of 5 s to {@code log}; with {@code forgedX}, its claim says robot 0 ended there. */
    private static RunResult record(Path log, String forgedX) throws IOException {
        try (Writer out = new java.io.OutputStreamWriter(new GZIPOutputStream(Files.newOutputStream(log)), StandardCharsets.UTF_8)) {
            CommandLogWriter w = new CommandLogWriter(out);
            RunResult r = Simulation.builder().arena("lab").controller("Braitenberg").seed(1).seconds(5)
                    .sampleMillis(Grader.SAMPLE_MILLIS).trace(new StringWriter()).record(w)
                    .onStart(s -> w.start(LogHeader.of(s, 5_000_000_000L, Grader.SAMPLE_MILLIS))).run();
            RunResult.RobotResult b = r.first();
            w.finish(String.format(Locale.ROOT, "{\"simulatedSeconds\": %s, \"traceSha256\": \"%s\", \"robots\": [{\"x\": %s,"
                    + " \"y\": %s, \"headingDeg\": %s, \"distanceMm\": %s, \"collisions\": %d, \"visitedPercent\": %s,"
                    + " \"controllerStatus\": \"stopped\"}], \"score\": {\"points\": %s}}", r.simulatedSeconds(), forgedX == null ? r.traceSha256() : new StringBuilder(r.traceSha256()).reverse(),
                    forgedX == null ? Double.toString(b.x()) : forgedX, b.y(), b.headingDeg(), b.distanceMm(), b.collisions(),
                    b.visitedPercent(), org.kheperasim.sim.task.Score.of(ArenaFormat.resolve("lab"),
                            org.kheperasim.sim.task.RunFacts.of(r)).points()));
            return r;
        }
    }

    private static ChildRun.Outcome outcome(RunStatus status, String diverged) {
        RunRecord r = new RunRecord("amy", "lab", 1, status, 0, 0, 0, 5, "Robot", diverged == null ? "" : diverged, "",
                RunRecord.NO_SANDBOX);
        return new ChildRun.Outcome(r, 1, null, null, null, null, diverged);
    }
}
