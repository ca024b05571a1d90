package org.kheperasim.sim.grade;

import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.kheperasim.sim.commandlog.OpenLoopReplay;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.task.Score;

/**
 * What differs between a run's own result (its claim, the JSON of {@code run --json}) and the
 * grader's replay of its command log, said so that a person can find it: the field, and where (the
 * first robot whose end differs, and in what).
 */
final class Differences {
    private Differences() {
    }

    /**
     * @param claim  the run's own result, parsed
     * @param replay the replay
     * @param score  the replay's score, or null when the arena has no tasks
     * @return what differs, one line, or null when nothing does
     */
    static String of(Map<String, Object> claim, OpenLoopReplay.Outcome replay, Score score) {
        RunResult result = replay.result();
        String sha = result.traceSha256();
        if (!sha.equals(claim.get("traceSha256"))) {
            return "its trace's SHA-256 " + shortSha(claim.get("traceSha256")) + ", the replay's "
                    + shortSha(sha) + "; "
                    + where(claim, result);
        }
        if (!same(claim.get("simulatedSeconds"), result.simulatedSeconds())) {
            return "it says " + claim.get("simulatedSeconds") + " s simulated, the replay " + result.simulatedSeconds();
        }
        Object points = claim.get("score") instanceof Map<?, ?> s ? s.get("points") : null;
        if (score != null && !same(points, score.points())) {
            return "it says " + points + " points, the replay " + String.format(Locale.ROOT, "%.2f", score.points());
        }
        if (score == null && points != null) {
            return "it has a score, the arena no tasks";
        }
        return null;
    }

    /** @return where the run's end and the replay's first differ: simulated time, then each robot's end in order */
    static String where(Map<String, Object> claim, RunResult result) {
        if (!same(claim.get("simulatedSeconds"), result.simulatedSeconds())) {
            return "it ends at " + claim.get("simulatedSeconds") + " s, the replay at "
                    + result.simulatedSeconds() + " s";
        }
        if (!(claim.get("robots") instanceof List<?> robots) || robots.size() != result.robots().size()) {
            return "its robots are not the replay's " + result.robots().size();
        }
        for (int i = 0; i < robots.size(); i++) {
            RunResult.RobotResult r = result.robots().get(i);
            if (!(robots.get(i) instanceof Map<?, ?> m)) {
                return "robot " + i + " is not an object";
            }
            String[] names = {"x", "y", "headingDeg", "distanceMm", "collisions", "visitedPercent"};
            double[] values = {r.x(), r.y(), r.headingDeg(), r.distanceMm(), r.collisions(), r.visitedPercent()};
            for (int k = 0; k < names.length; k++) {
                if (!same(m.get(names[k]), values[k])) {
                    return "robot " + i + " ends with " + names[k] + " " + m.get(names[k]) + ", in the replay "
                            + String.format(Locale.ROOT, "%.4f", values[k]);
                }
            }
        }
        return "every robot ends where the replay's does: the traces differ on the way (a sample or a vision line)";
    }

    /** The run's JSON writes 10 significant digits. */
    static boolean same(Object claimed, double computed) {
        return claimed instanceof Number n
                && StrictMath.abs(n.doubleValue() - computed) <= 1e-7 * StrictMath.max(1, StrictMath.abs(computed));
    }

    private static String shortSha(Object sha) {
        String s = String.valueOf(sha);
        return s.length() > 12 ? s.substring(0, 12) + "..." : s;
    }
}
