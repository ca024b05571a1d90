package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.kheperasim.sim.files.AtomicFiles;
import org.kheperasim.sim.files.InputFileException;
import org.kheperasim.sim.files.TextFiles;
import org.kheperasim.sim.text.Shown;

/**
 * The grade report's files, written and read back: {@code results.csv} and {@code results.json}
 * (one entry per run, in the grading's order, with the ranking per arena), {@code report.txt} (the
 * table printed at the end) and {@code index.html} (with the pictures in {@code img/}). They hold
 * nothing that depends on the machine or the wall clock, so sharded and unsharded gradings of the
 * same submissions write the same bytes.
 */
public final class ReportFiles {
    /** The first field of {@code results.json}. */
    public static final String FORMAT = "khepera-grade 1";
    /** The columns of {@code results.csv}. */
    public static final String CSV_HEADER =
            "student,arena,seed,status,points,max,percent,simulated_s,controller,picture,detail,"
            + "made_in,page,rerun";

    /**
     * A report: the plan it covers, the slice made, and the runs.
     *
     * @param plan  the whole grading
     * @param shard the slice these runs are ({@link GradePlan.Shard#ALL} for a whole or merged report)
     * @param runs  the runs, in the plan's order
     */
    public record Report(GradePlan plan, GradePlan.Shard shard, List<RunRecord> runs) {
        /** Copies the list. */
        public Report {
            runs = List.copyOf(runs);
        }
    }

    /** The largest {@code results.json} read back, bytes (a run is about 300 bytes of it). */
    private static final long MAX_JSON_BYTES = 256L << 20;

    private ReportFiles() {
    }

    /** @param job a run @return the name its files share, e.g. {@code alice__maze__s3} */
    public static String runId(GradePlan.Job job) {
        return safe(job.student()) + "__" + safe(arenaLabel(job.arena())) + "__s" + job.seed();
    }

    /** @param arena an arena as given (a bundled name or a path) @return a short name for it */
    public static String arenaLabel(String arena) {
        String base = arena.substring(Math.max(arena.lastIndexOf('/'), arena.lastIndexOf('\\')) + 1);
        return base.endsWith(".arena") ? base.substring(0, base.length() - ".arena".length()) : base;
    }

    private static String safe(String s) {
        return s.replaceAll("[^A-Za-z0-9_.-]", "_");
    }

    /**
     * Writes every file of the report (not the pictures, which the runs made).
     *
     * @param report the report
     * @param out    the report folder
     */
    public static void write(Report report, Path out) {
        try {
            Files.createDirectories(out);
            AtomicFiles.write(out.resolve("results.csv"), csv(report.runs()));
            AtomicFiles.write(out.resolve("results.json"), json(report));
            AtomicFiles.write(out.resolve("report.txt"), TextTable.of(report.runs()));
            AtomicFiles.write(out.resolve("index.html"), HtmlReport.of(report));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the report in " + out + ": " + e.getMessage(), e);
        }
    }

    static String csv(List<RunRecord> runs) {
        StringBuilder sb = new StringBuilder(CSV_HEADER).append('\n');
        for (RunRecord r : runs) {
            sb.append(csvField(r.student())).append(',').append(csvField(r.arena())).append(',')
                    .append(r.seed()).append(',')
                    .append(r.status().word()).append(',').append(num(r.points())).append(',')
                    .append(num(r.max())).append(',')
                    .append(num(r.percent())).append(',')
                    .append(String.format(Locale.ROOT, "%.3f", r.simulatedSeconds()))
                    .append(',').append(csvField(r.controller())).append(',').append(csvField(r.picture())).append(',')
                    .append(csvField(r.detail())).append(',').append(r.madeIn()).append(',').append(csvField(r.page()))
                    .append(',').append(csvField(r.rerun())).append('\n');
        }
        return sb.toString();
    }

    static String json(Report report) {
        StringBuilder sb = new StringBuilder("{\n  \"format\": ").append(JsonValues.quote(FORMAT));
        sb.append(",\n  \"students\": ").append(strings(report.plan().students()));
        sb.append(",\n  \"arenas\": ").append(strings(report.plan().arenas()));
        sb.append(",\n  \"seeds\": ").append(report.plan().seeds());
        sb.append(",\n  \"shard\": ").append(JsonValues.quote(report.shard().toString()));
        sb.append(",\n  \"runs\": [");
        for (int i = 0; i < report.runs().size(); i++) {
            sb.append(i > 0 ? "," : "").append("\n    ").append(json(report.runs().get(i)));
        }
        sb.append("\n  ],\n  \"ranking\": {");
        boolean firstArena = true;
        for (Map.Entry<String, List<Ranking.Entry>> e : Ranking.of(report.runs()).entrySet()) {
            sb.append(firstArena ? "" : ",").append("\n    ").append(JsonValues.quote(e.getKey())).append(": [");
            firstArena = false;
            List<Ranking.Entry> ranked = e.getValue().stream().filter(Ranking.Entry::ranked).toList();
            for (int i = 0; i < ranked.size(); i++) {
                Ranking.Entry r = ranked.get(i);
                sb.append(i > 0 ? ", " : "").append("{\"rank\": ").append(r.rank()).append(", \"student\": ")
                        .append(JsonValues.quote(r.student())).append(", \"meanPercent\": ")
                        .append(num(r.meanPercent()))
                        .append(", \"meanPoints\": ").append(num(r.meanPoints())).append('}');
            }
            sb.append(']');
        }
        return sb.append("\n  }\n}\n").toString();
    }

    /** @param r a run @return it as one JSON object on one line (in {@code results.json} and the journal) */
    static String json(RunRecord r) {
        return new StringBuilder("{\"student\": ").append(JsonValues.quote(r.student()))
                .append(", \"arena\": ").append(JsonValues.quote(r.arena())).append(", \"seed\": ").append(r.seed())
                .append(", \"status\": ").append(JsonValues.quote(r.status().word()))
                .append(", \"points\": ").append(num(r.points())).append(", \"max\": ").append(num(r.max()))
                .append(", \"percent\": ").append(num(r.percent()))
                .append(", \"simulatedSeconds\": ").append(String.format(Locale.ROOT, "%.3f", r.simulatedSeconds()))
                .append(", \"controller\": ").append(JsonValues.quote(r.controller()))
                .append(", \"picture\": ").append(JsonValues.quote(r.picture()))
                .append(", \"detail\": ").append(JsonValues.quote(r.detail()))
                .append(", \"madeIn\": ").append(JsonValues.quote(r.madeIn()))
                .append(", \"page\": ").append(JsonValues.quote(r.page()))
                .append(", \"rerun\": ").append(JsonValues.quote(r.rerun())).append('}').toString();
    }

    /** @param r a run's JSON object, parsed @return the run */
    static RunRecord record(Map<String, Object> r) {
        return new RunRecord((String) r.get("student"), (String) r.get("arena"), ((Number) r.get("seed")).longValue(),
                RunStatus.ofWord((String) r.get("status")), dbl(r.get("points")), dbl(r.get("max")),
                dbl(r.get("percent")), dbl(r.get("simulatedSeconds")), (String) r.get("controller"),
                (String) r.get("detail"), (String) r.get("picture"), (String) r.get("madeIn"), (String) r.get("page"),
                r.get("rerun") instanceof String s ? s : "");
    }

    /**
     * Reads a {@code results.json} back.
     *
     * @param file the file
     * @return the report it holds
     * @throws IllegalArgumentException if it is not a grade report
     */
    @SuppressWarnings("unchecked")
    public static Report read(Path file) {
        Object parsed = JsonValues.parse(TextFiles.readUtf8(file, MAX_JSON_BYTES, "grade report",
                (line, what) -> new InputFileException(file.toString(), line, what)));
        if (!(parsed instanceof Map<?, ?> m) || !FORMAT.equals(m.get("format"))) {
            throw new IllegalArgumentException(file + " is not a grade report (no \"format\": \"" + FORMAT + "\")");
        }
        GradePlan plan = new GradePlan((List<String>) m.get("students"), (List<String>) m.get("arenas"),
                ((Number) m.get("seeds")).intValue());
        List<RunRecord> runs = new ArrayList<>();
        for (Object o : (List<Object>) m.get("runs")) {
            runs.add(record((Map<String, Object>) o));
        }
        return new Report(plan, GradePlan.Shard.parse((String) m.get("shard")), runs);
    }

    /**
     * Reads a {@code results.csv} back.
     *
     * @param file the file
     * @return its runs, in order
     */
    public static List<RunRecord> readCsv(Path file) {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + file + ": " + e.getMessage(), e);
        }
        // Reports written before a column was added read too: made_in, then page, then rerun.
        if (lines.isEmpty() || !CSV_HEADER.startsWith(lines.get(0)) || !lines.get(0).contains(",detail")) {
            throw new IllegalArgumentException(file + " does not start with the header " + CSV_HEADER);
        }
        List<RunRecord> out = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            List<String> f = csvSplit(line).stream().map(Shown::fromCsvCell).toList();
            out.add(new RunRecord(f.get(0), f.get(1), Long.parseLong(f.get(2)), RunStatus.ofWord(f.get(3)),
                    Double.parseDouble(f.get(4)), Double.parseDouble(f.get(5)), Double.parseDouble(f.get(6)),
                    Double.parseDouble(f.get(7)), f.get(8), f.get(10), f.get(9), f.size() > 11 ? f.get(11) : "",
                    f.size() > 12 ? f.get(12) : "", f.size() > 13 ? f.get(13) : ""));
        }
        return out;
    }

    /** @param d a value @return it rounded to 2 decimals, as the report writes it */
    public static double round2(double d) {
        return Double.parseDouble(String.format(Locale.ROOT, "%.2f", d));
    }

    /** A score as the report writes it: at most 2 decimals, no trailing zeros. */
    public static String num(double d) {
        String s = String.format(Locale.ROOT, "%.2f", d);
        s = s.replaceFirst("\\.?0+$", "");
        return s.equals("-0") ? "0" : s;
    }

    private static String strings(List<String> l) {
        StringBuilder sb = new StringBuilder("[");
        for (int i = 0; i < l.size(); i++) {
            sb.append(i > 0 ? ", " : "").append(JsonValues.quote(l.get(i)));
        }
        return sb.append(']').toString();
    }

    private static double dbl(Object o) {
        return ((Number) o).doubleValue();
    }

    /**
     * A text cell: one line, control characters escaped, never a formula ({@link Shown#csvCell}); numbers are written
     * as numbers.
     */
    private static String csvField(String s) {
        return Shown.csvCell(s);
    }

    private static List<String> csvSplit(String line) {
        List<String> out = new ArrayList<>();
        StringBuilder cur = new StringBuilder();
        boolean quoted = false;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (quoted) {
                if (c == '"' && i + 1 < line.length() && line.charAt(i + 1) == '"') {
                    cur.append('"');
                    i++;
                } else if (c == '"') {
                    quoted = false;
                } else {
                    cur.append(c);
                }
            } else if (c == '"') {
                quoted = true;
            } else if (c == ',') {
                out.add(cur.toString());
                cur.setLength(0);
            } else {
                cur.append(c);
            }
        }
        out.add(cur.toString());
        return out;
    }
}
