package org.kheperasim.sim.grade;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The students of one assignment (arena) ranked by their mean score over the seeds; a run that
 * failed counts with the points it earned before it failed (none, when it did not run). At equal
 * means, fewer runs not ok rank first, so a failure never ties a clean run; equal means with as many
 * runs not ok share a rank. A student with a run found {@link RunStatus#TAMPERED tampered}, or one
 * that {@link RunStatus#DIVERGED differed from its replay} in both makings, in an arena is not ranked
 * there until a person has looked: listed after the ranked ones, with rank 0.
 */
final class Ranking {
    /** The rule, as the report states it. */
    static final String RULE =
            "Ranked by mean score over the seeds (a run that failed keeps the points it earned before it"
            + " failed); at equal means, fewer runs not ok rank first, so a failure never ties a clean run;"
            + " equal means with as many runs not ok share a rank. A student with a tampered run, or a run that"
            + " differed from its replay twice, is not ranked (-).";

    /**
     * One student's line.
     *
     * @param rank        1 for the best; equal means share a rank; 0 for a student not ranked (tampered)
     * @param student     the student
     * @param meanPercent the mean of the runs' percentages
     * @param meanPoints  the mean of the runs' points
     * @param runs        the runs, by seed
     */
    record Entry(int rank, String student, double meanPercent, double meanPoints, List<RunRecord> runs) {
        /** @return false for a student left out of the ranking */
        boolean ranked() {
            return rank > 0;
        }
    }

    private Ranking() {
    }

    /**
     * @param runs every run of the grading
     * @return for each arena, in the order first seen, its ranking
     */
    static Map<String, List<Entry>> of(List<RunRecord> runs) {
        Map<String, Map<String, List<RunRecord>>> byArena = new LinkedHashMap<>();
        for (RunRecord r : runs) {
            byArena.computeIfAbsent(r.arena(), a -> new LinkedHashMap<>())
                    .computeIfAbsent(r.student(), s -> new ArrayList<>()).add(r);
        }
        Map<String, List<Entry>> out = new LinkedHashMap<>();
        byArena.forEach((arena, students) -> {
            List<Entry> entries = new ArrayList<>();
            students.forEach((student, list) -> {
                List<RunRecord> sorted = list.stream().sorted(Comparator.comparingLong(RunRecord::seed)).toList();
                double pct = sorted.stream().mapToDouble(RunRecord::percent).average().orElse(0);
                double pts = sorted.stream().mapToDouble(RunRecord::points).average().orElse(0);
                entries.add(new Entry(0, student, ReportFiles.round2(pct), ReportFiles.round2(pts), sorted));
            });
            entries.sort(Comparator.comparing(Ranking::tampered)
                    .thenComparing(Comparator.comparingDouble(Entry::meanPercent)
                    .reversed()).thenComparingLong(Ranking::notOk).thenComparing(Entry::student));
            List<Entry> ranked = new ArrayList<>();
            for (int i = 0; i < entries.size(); i++) {
                Entry e = entries.get(i);
                Entry before = i > 0 ? entries.get(i - 1) : null;
                int rank = tampered(e) ? 0
                        : before != null && before.meanPercent() == e.meanPercent() && notOk(before) == notOk(e)
                                ? ranked.get(i - 1).rank() : i + 1;
                ranked.add(new Entry(rank, e.student(), e.meanPercent(), e.meanPoints(), e.runs()));
            }
            out.put(arena, ranked);
        });
        return out;
    }

    /** @return how many of a student's runs were not ok */
    static long notOk(Entry e) {
        return e.runs().stream().filter(r -> r.status() != RunStatus.OK).count();
    }

    private static boolean tampered(Entry e) {
        return e.runs().stream().anyMatch(r -> r.status() == RunStatus.TAMPERED || r.status() == RunStatus.DIVERGED);
    }
}
