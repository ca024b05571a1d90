package org.kheperasim.sim.grade;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.Map;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.commandlog.CommandLogReader;
import org.kheperasim.sim.commandlog.LogFormatException;
import org.kheperasim.sim.commandlog.OpenLoopReplay;
import org.kheperasim.sim.commandlog.ReplayMismatchException;
import org.kheperasim.sim.commandlog.TornLogException;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;
import org.kheperasim.sim.web.RunOutcome;
import org.kheperasim.sim.web.RunPageRecorder;

/**
 * The grader's judgement of one child run: it replays the run's command log in its own engine, with
 * no student code, scores the replay, and compares the run's own result with it. A result that
 * differs, or a log that does not fit the run, from a JVM that ended normally (exit status 0 or 1) is
 * {@link RunStatus#DIVERGED}, and the judgement says so ({@link Judged#diverged}) so that the grader
 * makes the run again once ({@link Rerun}): an honest run always replays exactly, and a difference
 * that does not repeat is no evidence of anything. The same from a JVM that ended otherwise, a result
 * that is not the simulator's JSON, or a JVM that ended with success without a whole log is
 * {@link RunStatus#TAMPERED}. Either way the reason says what differs and where. An exit status other
 * than the one the run's result calls for is an error; only then does the run's own word on how each
 * controller ended count (it is the status, never the score).
 */
final class Verdict {
    /** The most of a command log kept, compressed (a long run of a busy controller: a few hundred KB). */
    static final long MAX_LOG_BYTES = 256L << 20;
    /** The most text read from it, uncompressed. */
    static final long MAX_LOG_TEXT = 2L << 30;

    /**
     * What a child left.
     *
     * @param killed  true when the grader killed it at the wall-clock limit
     * @param exit    its exit status
     * @param err     the tail of its standard error (folders of the submission taken out)
     * @param log     its command log as received (null when none came)
     * @param logCut  true when it sent more than {@link #MAX_LOG_BYTES}
     * @param madeIn  how it was made
     */
    record Child(boolean killed, int exit, String err, Path log, boolean logCut, String madeIn) {
    }

    /**
     * The judgement.
     *
     * @param record the run as the report holds it
     * @param page   what the run's page says besides the replay's samples (title, failures with the student's
     *               line, the replay's facts for the score), or null when there is no replay to show
     * @param tape   the replay's samples for the page, every {@link RunPageRecorder#PERIOD_MILLIS}, or null
     * @param diverged what differed from the replay, from a JVM that ended normally (the run is to be made again
     *               once), or null
     */
    record Judged(RunRecord record, RunOutcome page, RunPageRecorder tape, String diverged) {
        Judged(RunRecord record) {
            this(record, null, null, null);
        }

        Judged(RunRecord record, RunOutcome page, RunPageRecorder tape) {
            this(record, page, tape, null);
        }
    }

    private Verdict() {
    }

    /**
     * @param job   the run
     * @param sub   the submission
     * @param arena the arena
     * @param lim   the grading's limits
     * @param child what the child left
     * @param trace where the replay's trace goes
     * @return the run's record, and its page's facts when it was replayed
     */
    static Judged judge(GradePlan.Job job, Submission sub, Arena arena, ChildRun.Limits lim, Child child, Path trace) {
        String controller = sub.controller();
        if (child.killed() || child.exit() == ChildSide.WALL_LIMIT_EXIT) {
            return new Judged(ChildResults.noResult(job, controller, true, lim.wallSeconds(), child.exit(), child.err(),
                    child.madeIn()));
        }
        if (child.logCut()) {
            return new Judged(new RunRecord(job.student(), job.arena(), job.seed(), RunStatus.ERROR, 0, 0,
                    0, 0, controller,
                    "its command log passed the limit of " + (MAX_LOG_BYTES >> 20)
                            + " MiB (compressed) and was cut off", "",
                    child.madeIn()));
        }
        double seconds = lim.seconds() != null ? lim.seconds() : arena.assignment().secondsOr(600);
        OpenLoopReplay.Run run = new OpenLoopReplay.Run(arena, job.seed(), (long) StrictMath.rint(seconds * 1e9),
                lim.sampleMillis(), Collections.nCopies(arena.robots().size(), Settings.defaults()));
        OpenLoopReplay.Outcome replay;
        // The page's samples come from the replay's own snapshots, every 50 ms: a trace that fine would
        // cost the run and the replay five times the formatting of the trace's 250 ms lines.
        RunPageRecorder tape = new RunPageRecorder(arena, null);
        try (BufferedReader in = open(child.log());
                Writer out = Files.newBufferedWriter(trace, StandardCharsets.UTF_8)) {
            if (in == null) {
                throw new TornLogException(0, "no command log came");
            }
            replay = OpenLoopReplay.replay(run, new CommandLogReader(in), out, tape, RunPageRecorder.PERIOD_MILLIS);
        } catch (UncheckedIOException e) {
            deleteQuietly(trace);
            return new Judged(new RunRecord(job.student(), job.arena(), job.seed(), RunStatus.ERROR, 0, 0,
                    0, 0, controller,
                    "its command log could not be read: " + e.getMessage(), "", child.madeIn()));
        } catch (TornLogException e) {
            deleteQuietly(trace);
            // No whole log: the run did not end as the simulator ends it.
            return new Judged(ChildResults.noResult(job, controller, false, lim.wallSeconds(),
                    child.exit(), child.err(),
                    child.madeIn()));
        } catch (ReplayMismatchException | LogFormatException e) {
            deleteQuietly(trace);
            return difference(job, controller, child,
                    "its command log does not fit the run (" + e.getMessage() + ")", null, 0,
                    null, null);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot replay " + child.log() + ": " + e.getMessage(), e);
        }
        Score score = arena.assignment().hasTasks() ? Score.of(arena, RunFacts.of(replay.result())) : null;
        double reached = replay.result().simulatedSeconds();
        Map<String, Object> claim;
        try {
            @SuppressWarnings("unchecked")
            Map<String, Object> parsed = (Map<String, Object>) JsonValues.parse(replay.claim());
            claim = parsed;
        } catch (RuntimeException e) {
            RunRecord r = ChildResults.tampered(job, controller,
                    "its own result is not the simulator's JSON", score, reached,
                    child.madeIn());
            return new Judged(r, ChildResults.page(job, controller, Map.of(), replay.result(), r), tape);
        }
        String differs = Differences.of(claim, replay, score);
        if (differs != null) {
            return difference(job, controller, child,
                    "its own result differs from the replay of its command log (" + differs
                    + "); the score is the replay's", score, reached, replay, tape);
        }
        RunRecord r = ChildResults.fromClaim(job, controller, claim, score, reached, child.err(), child.madeIn());
        int expected = r.status() == RunStatus.OK ? 0 : 1;
        if (child.exit() != expected) {
            r = new RunRecord(r.student(), r.arena(), r.seed(), RunStatus.ERROR, r.points(), r.max(), r.percent(),
                    r.simulatedSeconds(), controller, "exit status " + child.exit() + " after a whole run that ended "
                    + r.status().label() + " (" + expected + " expected)", "", child.madeIn());
        }
        return new Judged(r, ChildResults.page(job, controller, claim, replay.result(), r), tape);
    }

    /**
     * A result that differs from the replay, or a log that does not fit the run: from a JVM that ended
     * normally, a difference to make the run again for; from one that ended otherwise, evidence of tampering.
     */
    private static Judged difference(GradePlan.Job job, String controller, Child child, String what,
            Score score, double reached,
            OpenLoopReplay.Outcome replay, RunPageRecorder tape) {
        boolean normal = child.exit() == 0 || child.exit() == 1;
        RunRecord t = ChildResults.tampered(job, controller,
                normal ? what : "its JVM ended with exit status " + child.exit()
                + ", which the simulator never gives, and " + what, score, reached, child.madeIn());
        RunRecord r = normal
                ? new RunRecord(t.student(), t.arena(), t.seed(), RunStatus.DIVERGED, t.points(), t.max(), t.percent(),
                t.simulatedSeconds(), t.controller(), t.detail(), t.picture(), t.madeIn()) : t;
        RunOutcome page = replay == null ? null : ChildResults.page(job, controller, Map.of(), replay.result(), r);
        return new Judged(r, page, replay == null ? null : tape, normal ? t.detail() : null);
    }

    private static BufferedReader open(Path log) throws IOException {
        if (log == null || !Files.isRegularFile(log) || Files.size(log) == 0) {
            return null;
        }
        return org.kheperasim.sim.commandlog.LogChannel.read(log, MAX_LOG_TEXT);
    }

    private static void deleteQuietly(Path p) {
        try {
            Files.deleteIfExists(p);
        } catch (IOException e) {
            // left behind: a trace without a picture
        }
    }
}
