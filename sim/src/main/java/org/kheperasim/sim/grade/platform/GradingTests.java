package org.kheperasim.sim.grade.platform;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.kheperasim.sim.grade.GradeDeadline;
import org.kheperasim.sim.grade.ReportFiles;
import org.kheperasim.sim.grade.RunRecord;
import org.kheperasim.sim.grade.RunStatus;
import org.kheperasim.sim.text.Shown;

/**
 * A grade report as the platforms take it: per submission one test per arena and seed, with the run's
 * points, how it ended (the failure with the student's file and line, a verdict with its reason), its
 * picture, hidden when its arena is one of the hidden ones; a submission that does not compile, holds
 * nothing, or whose controller was refused at load is not gradable, apart from a zero.
 */
public final class GradingTests {
    private GradingTests() {
    }

    /**
     * @param report the grading's report
     * @param hidden the arenas (as given to {@code --arenas}) whose runs the students must not see
     * @return one result per submission, in the report's order
     */
    public static List<PlatformResult> of(ReportFiles.Report report, Set<String> hidden) {
        for (String h : hidden) {
            if (!report.plan().arenas().contains(h)) {
                throw new IllegalArgumentException("--hidden " + h + ": not one of the arenas graded ("
                        + String.join(", ",
                        report.plan().arenas()) + "); give each hidden arena in --arenas too, written the same way");
            }
        }
        Map<String, List<RunRecord>> byStudent = new LinkedHashMap<>();
        for (RunRecord r : report.runs()) {
            byStudent.computeIfAbsent(r.student(), s -> new ArrayList<>()).add(r);
        }
        List<PlatformResult> out = new ArrayList<>();
        for (Map.Entry<String, List<RunRecord>> e : byStudent.entrySet()) {
            out.add(one(e.getKey(), e.getValue(), report.plan().arenas(), hidden));
        }
        return out;
    }

    private static PlatformResult one(String student, List<RunRecord> runs, List<String> arenas, Set<String> hidden) {
        List<PlatformTest> tests = new ArrayList<>();
        String problem = "";
        int notMade = 0;
        int ok = 0;
        for (RunRecord r : runs) {
            boolean isHidden = hidden.contains(r.arena());
            String label = ReportFiles.arenaLabel(r.arena());
            tests.add(new PlatformTest(label + ", seed " + r.seed(),
                    (arenas.indexOf(r.arena()) + 1) + "." + r.seed(), r.points(),
                    r.max(), r.status() == RunStatus.OK, r.status().word(), output(r), isHidden,
                    r.picture(), r.arena()));
            if (problem.isEmpty() && notGradable(r)) {
                problem = r.status().label() + ": " + Shown.line(r.detail());
            }
            notMade += GradeDeadline.notMade(r) ? 1 : 0;
            ok += r.status() == RunStatus.OK ? 1 : 0;
        }
        List<PlatformResult.Leader> board = new ArrayList<>();
        for (String a : arenas) {
            if (!hidden.contains(a)) {
                runs.stream().filter(r -> r.arena().equals(a)).mapToDouble(RunRecord::percent).average().ifPresent(m ->
                        board.add(new PlatformResult.Leader(ReportFiles.arenaLabel(a) + " mean %",
                                ReportFiles.round2(m))));
            }
        }
        double score = runs.stream().mapToDouble(RunRecord::points).sum();
        double max = runs.stream().mapToDouble(RunRecord::max).sum();
        String summary = problem.isEmpty()
                ? String.format(Locale.ROOT, "%s: %s of %s points over %d runs (%d ok, %d not ok)", Shown.line(student),
                        ReportFiles.num(score), ReportFiles.num(max), runs.size(), ok, runs.size() - ok)
                : "not gradable: " + problem;
        if (notMade > 0) {
            summary += String.format(Locale.ROOT,
                    "; the grading's deadline passed before %d of the %d runs were made: they"
                    + " count 0, the others keep their points", notMade, runs.size());
        }
        return new PlatformResult(student, tests, problem.isEmpty(), problem, board, summary);
    }

    /** Does not compile, holds nothing, or its controller was refused at load: no run of it could be made. */
    static boolean notGradable(RunRecord r) {
        return r.status() == RunStatus.COMPILE_FAILED || r.status() == RunStatus.NOTHING_HANDED_IN
                || (r.status() == RunStatus.BROKE_RULE && r.detail().contains("refused at load"));
    }

    /** The run's points and how it ended, its student text escaped ({@link Shown#line}). */
    static String output(RunRecord r) {
        String head = String.format(Locale.ROOT, "%s: %s of %s points (%s%%) in %.3f simulated s", r.status().label(),
                ReportFiles.num(r.points()), ReportFiles.num(r.max()), ReportFiles.num(r.percent()),
                r.simulatedSeconds());
        StringBuilder sb = new StringBuilder(head);
        if (!r.controller().isEmpty()) {
            sb.append("\ncontroller: ").append(Shown.line(r.controller()));
        }
        if (!r.detail().isEmpty()) {
            sb.append('\n').append(Shown.line(r.detail()));
        }
        return sb.toString();
    }
}
