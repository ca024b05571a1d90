package org.kheperasim.sim.grade;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.Locale;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.run.BoundedConsole;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.task.Score;

/**
 * A graded run's own result, as it hands it to the grader at the end of its command log: one line of
 * JSON with what the grader compares with its replay (the trace's SHA-256, the simulated time, the
 * score) and how each controller ended, with the simulator's report of a failure ({@link Verdict},
 * {@link ChildResults}). Numbers have 9 significant digits, as {@code run --json} writes them.
 */
final class Claim {
    private static final MathContext SIGNIFICANT = new MathContext(9);

    private Claim() {
    }

    /**
     * @param result   the run's result
     * @param score    its score, or null when the arena has no tasks
     * @param failures the controllers' failure reports seen on the run's console
     * @return the claim, one line of JSON
     */
    static String of(RunResult result, Score score, FailureLines failures) {
        StringBuilder j = new StringBuilder("{");
        j.append("\"seed\":").append(result.seed());
        j.append(",\"arena\":").append(JsonValues.quote(result.arena()));
        j.append(",\"controller\":").append(JsonValues.quote(result.controller()));
        j.append(",\"simulatedSeconds\":").append(num(result.simulatedSeconds()));
        j.append(",\"traceSha256\":").append(JsonValues.quote(result.traceSha256()));
        j.append(",\"robots\":[");
        for (int i = 0; i < result.robots().size(); i++) {
            RunResult.RobotResult r = result.robots().get(i);
            j.append(i > 0 ? "," : "").append("{\"name\":").append(JsonValues.quote(r.name()));
            j.append(",\"controllerStatus\":").append(JsonValues.quote(r.status().name().toLowerCase(Locale.ROOT)));
            // A fault's message is bounded like output: an exception's message of any size is a few KB here.
            j.append(",\"failure\":").append(JsonValues.quote(BoundedConsole.bounded(r.failure())));
            if (r.status().failed()) {
                ConsoleLine thrown = failures.thrown(r.name());
                String at = thrown == null ? null : FailureText.studentFrame(thrown.text());
                if (at != null) {
                    j.append(",\"failureAt\":").append(JsonValues.quote(at));
                }
                ConsoleLine report = failures.first(r.name());
                if (report != null) {
                    j.append(",\"failureSeconds\":").append(num(report.timeNanos() / 1e9));
                }
            }
            j.append('}');
        }
        j.append(']');
        if (score != null) {
            j.append(",\"score\":{\"points\":").append(num(score.points())).append(",\"max\":").append(num(score.max()))
                    .append(",\"percent\":").append(num(score.percent())).append('}');
        }
        return j.append('}').toString();
    }

    private static String num(double value) {
        return Double.isFinite(value)
                ? new BigDecimal(value).round(SIGNIFICANT).stripTrailingZeros().toPlainString() : "null";
    }
}
