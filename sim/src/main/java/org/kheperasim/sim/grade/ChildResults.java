package org.kheperasim.sim.grade;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.kheperasim.sim.run.BoundedConsole;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;
import org.kheperasim.sim.web.RunOutcome;

/**
 * Turns what a child run left into a {@link RunRecord}: its own result (the claim at the end of its
 * command log, for how each controller ended and why) with the score the grader computed by
 * replaying the log; or, when there is no whole log, its exit status and the tail of its standard
 * error (killed at the wall-clock limit, out of heap, refused at load). Standard output is never
 * read for a result: a controller prints there.
 */
final class ChildResults {
    private static final int MAX_DETAIL = 300;

    private ChildResults() {
    }

    /**
     * A run whose log was whole and replayed to the same result.
     *
     * @param job        the run
     * @param controller the controller class
     * @param claim      the run's own result, parsed
     * @param score      the score of the replay, or null when the arena has no tasks
     * @param seconds    simulated seconds the replay reached
     * @param err        the tail of the run's standard error
     * @param madeIn     how the run was made
     * @return the record
     */
    static RunRecord fromClaim(GradePlan.Job job, String controller, Map<String, Object> claim,
            Score score, double seconds,
            String err, String madeIn) {
        RunStatus status = RunStatus.OK;
        String failure = null;
        String at = null;
        Object robots = claim.get("robots");
        if (robots instanceof List<?> list) {
            for (Object o : list) {
                if (o instanceof Map<?, ?> robot) {
                    RunStatus s = ofController(String.valueOf(robot.get("controllerStatus")));
                    if (s != RunStatus.OK) {
                        status = s;
                        // What it threw, and where in the student's code; for the other faults the run's
                        // first error line (below; its result's text is its last error, which may be a
                        // later one), else its result's text, without what depends on the machine.
                        Object text = robot.get("failure");
                        failure = text == null ? null : s == RunStatus.THREW ? String.valueOf(text)
                                : fault(err) != null ? fault(err) : FailureText.machineFree(String.valueOf(text));
                        at = robot.get("failureAt") instanceof String frame ? frame : null;
                        break;
                    }
                }
            }
        }
        StringBuilder detail = new StringBuilder();
        if (score != null) {
            for (Score.Part p : score.parts()) {
                detail.append(detail.length() > 0 ? "; " : "").append(p.task().replaceFirst("^task ", "")).append(": ")
                        .append(p.detail());
            }
        }
        if (status == RunStatus.EXCEEDED_MEMORY) {
            failure = outOfMemory(controller);
        } else if (failure == null && status != RunStatus.OK) {
            failure = fault(err);
        }
        if (failure != null) {
            // The student's line is kept whole, however long the message before it.
            String where = at == null ? "" : " at " + at;
            detail.insert(0, shorten(failure, MAX_DETAIL - where.length()) + where
                    + (detail.length() > 0 ? " | " : ""));
        }
        return new RunRecord(job.student(), job.arena(), job.seed(), status, score == null ? 0 : score.points(),
                score == null ? 0 : score.max(), score == null ? 0 : score.percent(), seconds, controller,
                withDropped(detail.toString(), err), "", madeIn);
    }

    /**
     * What a replayed run's page says besides its samples: who and what it was, each controller that
     * failed with the report's words (the student's line where it threw) and when, and the replay's
     * facts for the score (its floor coverage and region times, exactly the report's score).
     *
     * @param job        the run
     * @param controller the controller class
     * @param claim      the run's own result, parsed (empty when it was not the simulator's)
     * @param replay     the result of the grader's replay
     * @param record     the run as the report holds it
     * @return the page's outcome
     */
    static RunOutcome page(GradePlan.Job job, String controller, Map<String, Object> claim, RunResult replay,
            RunRecord record) {
        String title = job.student() + ": " + controller.substring(controller.lastIndexOf('.') + 1) + " in "
                + ReportFiles.arenaLabel(job.arena()) + " · seed " + job.seed();
        List<RunOutcome.Failure> failures = new ArrayList<>();
        if (claim.get("robots") instanceof List<?> robots) {
            for (int i = 0; i < robots.size(); i++) {
                if (robots.get(i) instanceof Map<?, ?> robot) {
                    String word = String.valueOf(robot.get("controllerStatus"));
                    if (ofController(word) == RunStatus.OK) {
                        continue;
                    }
                    String text = robot.get("failure") == null ? "" : String.valueOf(robot.get("failure"));
                    RunStatus s = ofController(word);
                    String message = s == RunStatus.THREW
                            ? text + (robot.get("failureAt") instanceof String at ? " at " + at : "")
                            : s == RunStatus.EXCEEDED_MEMORY ? outOfMemory(controller) : FailureText.machineFree(text);
                    double seconds = robot.get("failureSeconds") instanceof Number n ? n.doubleValue() : Double.NaN;
                    failures.add(new RunOutcome.Failure(i, seconds, word, message));
                }
            }
        }
        if (failures.isEmpty() && record.status() != RunStatus.OK) {
            title += " · " + record.status().label()
                    + (record.status() == RunStatus.TAMPERED || record.status() == RunStatus.DIVERGED
                    ? " (the replay's points)" : "");
        }
        return new RunOutcome(title, failures, RunFacts.of(replay));
    }

    /** The heap watch or an OutOfMemoryError, depending on the collector's timing: one text for both. */
    private static String outOfMemory(String controller) {
        return "controller " + controller + " allocated without bound and was stopped at the run's heap limit";
    }

    /**
     * A run without a whole log: what its exit status and standard error tell.
     *
     * @param job        the run
     * @param controller the controller class
     * @param killed     true when the grader killed it at the wall-clock limit
     * @param wallLimit  that limit, s
     * @param exit       its exit status
     * @param err        the tail of its standard error
     * @param madeIn     how the run was made
     * @return the record: never ok
     */
    static RunRecord noResult(GradePlan.Job job, String controller, boolean killed, double wallLimit,
            int exit, String err,
            String madeIn) {
        RunStatus status;
        String detail;
        if (killed || exit == ChildSide.WALL_LIMIT_EXIT) {
            status = RunStatus.HUNG;
            detail = String.format(Locale.ROOT, "no result within the wall-clock limit of %.0f s; the run was killed",
                    wallLimit);
        } else if (err.contains("OutOfMemoryError")) {
            status = RunStatus.EXCEEDED_MEMORY;
            detail = "the run's JVM ran out of heap (exit status " + exit + ")";
        } else if (err.contains(" was refused: ")) {
            status = RunStatus.BROKE_RULE;
            detail = refusal(lastLine(err, " was refused: "));
        } else if (exit == 0) {
            // The simulator hands its result over before it ends the JVM: something else ended it.
            status = RunStatus.TAMPERED;
            detail = "the run's JVM ended with success (exit status 0) without handing over its command log and result:"
                    + " something other than the simulator ended it; what it printed is not a result";
        } else {
            status = RunStatus.ERROR;
            detail = (exit > 128 ? "killed by signal " + (exit - 128) + " (exit status " + exit + ")"
                    : "exit status " + exit)
                    + ": " + lastLine(err, "");
        }
        return new RunRecord(job.student(), job.arena(), job.seed(), status, 0, 0, 0, 0, controller,
                withDropped(shorten(detail), err), "", madeIn);
    }

    /**
     * @param job        the run
     * @param controller the controller class
     * @param why        what was found
     * @param score      the score of the replay of its command log, or null (none, or the log does not replay)
     * @param seconds    simulated seconds the replay reached (0 without one)
     * @param madeIn     how the run was made
     * @return a run found tampering, with what the replay says its robot did (never what it says itself)
     */
    static RunRecord tampered(GradePlan.Job job, String controller, String why, Score score, double seconds,
            String madeIn) {
        return new RunRecord(job.student(), job.arena(), job.seed(), RunStatus.TAMPERED,
                score == null ? 0 : score.points(),
                score == null ? 0 : score.max(), score == null ? 0 : score.percent(), seconds, controller,
                shorten(why), "",
                madeIn);
    }

    /** How much a run printed and kept, as its console's note says it: {@code printed 48 MB; kept the first 1 MB}. */
    private static final java.util.regex.Pattern OUTPUT = java.util.regex.Pattern.compile("khepera-sim: "
            + BoundedConsole.OUTPUT_DROPPED + " (\\S+ \\S+) of controller output; kept the first (\\S+ \\S+) ");
    /** The same as a record's detail ends with it. */
    private static final java.util.regex.Pattern DETAIL = java.util.regex.Pattern.compile(
            "(?<=^|\\| )" + BoundedConsole.OUTPUT_DROPPED + " \\S+ \\S+; kept the first \\S+ \\S+$");

    /** The run's note on controller output over its limit, added to the detail. */
    private static String withDropped(String detail, String err) {
        String note = outputNote(err);
        return note == null ? detail : detail + (detail.isEmpty() ? "" : " | ") + note;
    }

    /**
     * @param text a run's standard error, or a record's detail
     * @return what the run printed and kept, {@code printed 48 MB; kept the first 1 MB}, or null when it kept all
     */
    static String outputNote(String text) {
        java.util.regex.Matcher m = OUTPUT.matcher(text);
        if (m.find()) {
            return BoundedConsole.OUTPUT_DROPPED + " " + m.group(1) + "; kept the first " + m.group(2);
        }
        java.util.regex.Matcher d = DETAIL.matcher(text);
        return d.find() ? d.group() : null;
    }

    /**
     * The simulator's report of a fault from the child's standard error ({@code [  1.000 s] ERROR Name: controller
     * Name (Class) called System.exit(3); the controller was stopped ...}), without what depends on the machine
     * (the heap's size and fill).
     */
    static String fault(String err) {
        for (String line : err.split("\\R")) {
            int e = line.indexOf("] ERROR ");
            int colon = e < 0 ? -1 : line.indexOf(": ", e);
            if (colon > 0 && line.indexOf("controller ", colon) == colon + 2) {
                return FailureText.machineFree(line.substring(colon + 2));
            }
        }
        return null;
    }

    /**
     * A class refused at load, told from the student's line on ({@code controller Filer was refused at load:
     * Filer.java:3: uses java.io.File: ...}), without the class file's path and the loader's words.
     */
    static String refusal(String line) {
        java.util.regex.Matcher where = java.util.regex.Pattern.compile("[\\w$]+\\.java:\\d+: ").matcher(line);
        java.util.regex.Matcher who = java.util.regex.Pattern.compile("controller \\S+ was refused").matcher(line);
        if (!where.find() || !who.find() || where.start() < who.end()) {
            return line.replaceFirst("^khepera-sim: error: ", "");
        }
        return who.group() + " at load: " + line.substring(where.start());
    }

    static RunStatus ofController(String s) {
        return switch (s) {
            case "failed" -> RunStatus.THREW;
            case "hung" -> RunStatus.HUNG;
            case "broke_rule" -> RunStatus.BROKE_RULE;
            case "exceeded_memory" -> RunStatus.EXCEEDED_MEMORY;
            default -> RunStatus.OK; // finished, stopped, running (at the end), not_started
        };
    }

    private static String lastLine(String text, String containing) {
        String[] lines = text.split("\\R");
        for (int i = lines.length - 1; i >= 0; i--) {
            String l = lines[i].strip();
            if (!l.isEmpty() && l.contains(containing) && !l.startsWith("at ")) {
                return l;
            }
        }
        return "(no message)";
    }

    private static String shorten(String s) {
        return shorten(s, MAX_DETAIL);
    }

    private static String shorten(String s, int max) {
        String one = s.replaceAll("\\s+", " ").strip();
        return one.length() <= max ? one : one.substring(0, StrictMath.max(0, max - 3)) + "...";
    }
}
