package org.kheperasim.sim.grade;

import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Collectors;
import org.kheperasim.sim.text.Shown;

/**
 * The report as a terminal table: per arena, the students ranked, with each seed's score (and its
 * status when not ok), then every run not ok with its detail (the student's line where it threw), and every
 * run ok whose controller printed past the run's limit, with how much it printed and kept. Names and
 * details are shown as {@link Shown#line} shows them: one line each, their control characters escaped.
 */
final class TextTable {
    private TextTable() {
    }

    static String of(List<RunRecord> runs) {
        StringBuilder sb = new StringBuilder();
        Map<RunStatus, Integer> counts = new EnumMap<>(RunStatus.class);
        runs.forEach(r -> counts.merge(r.status(), 1, Integer::sum));
        for (Map.Entry<String, List<Ranking.Entry>> e : Ranking.of(runs).entrySet()) {
            List<Ranking.Entry> entries = e.getValue();
            int nameWidth = StrictMath.max(7,
                    entries.stream().mapToInt(x -> Shown.line(x.student()).length()).max().orElse(7));
            double max = entries.isEmpty() || entries.get(0).runs().isEmpty() ? 0
                    : entries.stream().flatMap(x -> x.runs().stream()).mapToDouble(RunRecord::max).max().orElse(0);
            sb.append("Arena ").append(Shown.line(e.getKey()))
                    .append(max > 0 ? " (" + ReportFiles.num(max) + " points)" : " (no tasks)")
                    .append('\n');
            sb.append(String.format(Locale.ROOT, "%4s  %-" + nameWidth + "s  %7s  %7s  %s%n", "rank",
                    "student", "score%",
                    "points", "score% by seed"));
            for (Ranking.Entry x : entries) {
                String seeds = x.runs().stream().map(TextTable::seed).collect(Collectors.joining(" | "));
                sb.append(String.format(Locale.ROOT, "%4s  %-" + nameWidth + "s  %7s  %7s  %s%n",
                        x.ranked() ? x.rank() : "-", Shown.line(x.student()),
                        ReportFiles.num(x.meanPercent()), ReportFiles.num(x.meanPoints()), seeds));
            }
            List<RunRecord> failed =
                    entries.stream().flatMap(x -> x.runs().stream()).filter(r -> r.status() != RunStatus.OK)
                    .toList();
            if (!failed.isEmpty()) {
                sb.append("Runs not ok:\n");
                for (RunRecord r : failed) {
                    sb.append("  ").append(Shown.line(r.student())).append(", seed ").append(r.seed()).append(": ")
                            .append(r.status().label())
                            .append(r.detail().isEmpty() ? "" : ": " + Shown.line(r.detail())).append('\n');
                }
            }
            List<RunRecord> cut = entries.stream().flatMap(x -> x.runs().stream())
                    .filter(r -> r.status() == RunStatus.OK && ChildResults.outputNote(r.detail()) != null).toList();
            if (!cut.isEmpty()) {
                sb.append("Output cut at the run's limit:\n");
                for (RunRecord r : cut) {
                    sb.append("  ").append(Shown.line(r.student())).append(", seed ").append(r.seed()).append(": ")
                            .append(ChildResults.outputNote(r.detail())).append('\n');
                }
            }
            sb.append('\n');
        }
        sb.append(Ranking.RULE).append('\n');
        sb.append(runs.size()).append(" runs: ").append(counts.entrySet().stream()
                .map(c -> c.getValue() + " " + c.getKey().label()).collect(Collectors.joining(", ")))
                .append("; ").append(madeIn(runs)).append("; ").append(reruns(runs)).append('\n');
        for (RunRecord r : runs) {
            if (r.madeAgain()) {
                sb.append("  made again: ").append(Shown.line(r.student())).append(", ").append(Shown.line(r.arena()))
                        .append(", seed ").append(r.seed())
                        .append(": the first time ").append(Shown.line(r.rerun())).append('\n');
            }
        }
        return sb.toString();
    }

    /** @return a seed's entry in the table: its score, %, and its status when not ok, e.g. {@code 4 (threw)} */
    static String seed(RunRecord r) {
        return ReportFiles.num(r.percent()) + (r.status() == RunStatus.OK ? "" : " (" + r.status().label() + ")");
    }

    /** @return how many runs were made again because their first result differed from the replay */
    static String reruns(List<RunRecord> runs) {
        long again = runs.stream().filter(RunRecord::madeAgain).count();
        return again == 0 ? "0 reruns" : again + (again == 1 ? " rerun" : " reruns")
                + " (a result that differed from its replay, made again once)";
    }

    /** @return how the runs were made: all in the sandbox, none, or how many each way */
    static String madeIn(List<RunRecord> runs) {
        long boxed = runs.stream().filter(r -> r.madeIn().equals(RunRecord.SANDBOX)).count();
        long bare = runs.stream().filter(r -> r.madeIn().equals(RunRecord.NO_SANDBOX)).count();
        if (bare == 0) {
            return boxed == 0 ? "none was run" : "every run made in the sandbox";
        }
        return boxed == 0 ? "made WITHOUT the sandbox (--no-sandbox)"
                : boxed + " made in the sandbox, " + bare + " WITHOUT it (--no-sandbox)";
    }
}
