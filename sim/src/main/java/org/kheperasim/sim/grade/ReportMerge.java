package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.kheperasim.sim.files.AtomicFiles;

/**
 * Joins the reports of the shards of one grading into the report of the whole: the same files,
 * byte for byte, as one unsharded grading writes. Refuses shards of different gradings, a shard
 * given twice and a missing shard, naming it.
 */
public final class ReportMerge {
    private ReportMerge() {
    }

    /**
     * @param shardFolders the shards' report folders (each with its {@code results.json} and {@code img/})
     * @param out          the merged report's folder
     * @return the merged report
     * @throws IllegalArgumentException if the shards do not make one whole grading
     */
    public static ReportFiles.Report merge(List<Path> shardFolders, Path out) {
        if (shardFolders.isEmpty()) {
            throw new IllegalArgumentException(
                    "grade merge: give the shards' report folders, e.g. grade merge --out report shard-*");
        }
        GradePlan plan = null;
        Map<Integer, Path> seen = new TreeMap<>();
        int n = 0;
        Map<Integer, RunRecord> byIndex = new HashMap<>();
        StringBuilder timings = new StringBuilder(Grader.TIMINGS_HEADER);
        for (Path folder : shardFolders) {
            Path file = folder.resolve("results.json");
            if (!Files.isRegularFile(file)) {
                throw new IllegalArgumentException("grade merge: " + folder
                        + " holds no results.json; give the --out folder of a 'grade --shard K/N' run");
            }
            ReportFiles.Report r = ReportFiles.read(file);
            if (plan == null) {
                plan = r.plan();
                n = r.shard().n();
            } else if (!plan.equals(r.plan()) || n != r.shard().n()) {
                throw new IllegalArgumentException("grade merge: " + folder
                        + " is a shard of another grading (its submissions,"
                        + " arenas, seeds or number of shards differ from " + shardFolders.get(0) + ")");
            }
            Path before = seen.put(r.shard().k(), folder);
            if (before != null) {
                throw new IllegalArgumentException("grade merge: shard " + r.shard() + " is given twice (" + before
                        + " and " + folder + ")");
            }
            List<GradePlan.Job> jobs = plan.shard(r.shard());
            if (jobs.size() != r.runs().size()) {
                throw new IllegalArgumentException("grade merge: " + folder + " holds " + r.runs().size()
                        + " runs, but shard "
                        + r.shard() + " has " + jobs.size() + "; make that shard again");
            }
            for (int i = 0; i < jobs.size(); i++) {
                byIndex.put(jobs.get(i).index(), r.runs().get(i));
            }
            copyFiles(folder, out, r.runs());
            appendTimings(folder, timings);
        }
        for (int k = 1; k <= n; k++) {
            if (!seen.containsKey(k)) {
                throw new IllegalArgumentException("grade merge: shard " + k + "/" + n
                        + " is missing; make it with grade --shard "
                        + k + "/" + n + " and give its folder too");
            }
        }
        List<RunRecord> runs = new ArrayList<>();
        for (GradePlan.Job j : plan.jobs()) {
            runs.add(byIndex.get(j.index()));
        }
        ReportFiles.Report merged = new ReportFiles.Report(plan, GradePlan.Shard.ALL, runs);
        ReportFiles.write(merged, out);
        try {
            AtomicFiles.write(out.resolve("timings.csv"), timings.toString());
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write timings.csv: " + e.getMessage(), e);
        }
        return merged;
    }

    /** The runs' pictures and pages, each saved atomically (a reader of the merged report never sees half a file). */
    private static void copyFiles(Path from, Path to, List<RunRecord> runs) {
        try {
            for (RunRecord r : runs) {
                for (String file : new String[] {r.picture(), r.page()}) {
                    if (!file.isEmpty()) {
                        Path target = to.resolve(file);
                        Files.createDirectories(target.getParent());
                        AtomicFiles.write(target, Files.readAllBytes(from.resolve(file)));
                    }
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot copy the pictures and pages of " + from + ": " + e.getMessage(), e);
        }
    }

    private static void appendTimings(Path folder, StringBuilder timings) {
        Path t = folder.resolve("timings.csv");
        try {
            if (Files.isRegularFile(t)) {
                List<String> lines = Files.readAllLines(t);
                // A shard of an earlier version has no page_s: its runs had no page.
                boolean pages = !lines.isEmpty() && lines.get(0).endsWith(",page_s");
                lines.stream().skip(1).forEach(l -> timings.append(l).append(pages ? "" : ",0.000").append('\n'));
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + t + ": " + e.getMessage(), e);
        }
    }
}
