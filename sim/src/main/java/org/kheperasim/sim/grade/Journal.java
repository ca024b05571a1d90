package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * The grading's journal, {@code journal.jsonl} in the report folder: a first line that says which
 * grading it is, then one line per finished run, appended and forced to disk as the run ends. A
 * grading started again on the same folder reads it, keeps the runs it holds and makes only the
 * others, so nothing finished is lost to a {@code kill -9}, a lost node or Ctrl-C. The last line may
 * be torn (the grader was killed while writing it): it is left out and cut off, and its run is made
 * again.
 */
final class Journal implements AutoCloseable {
    /** The first field of the journal's first line. */
    static final String FORMAT = "khepera-grade-journal 1";
    static final String FILE = "journal.jsonl";

    /**
     * A run the journal holds.
     *
     * @param record      the run as the report holds it
     * @param wallSeconds real time it took, s (for {@code timings.csv})
     * @param pageSeconds real time its web page took to write, s (for {@code timings.csv})
     */
    record Entry(RunRecord record, double wallSeconds, double pageSeconds) {
        /** A run without a page. */
        Entry(RunRecord record, double wallSeconds) {
            this(record, wallSeconds, 0);
        }
    }

    private final FileChannel out;
    private final Map<Integer, Entry> done;

    private Journal(FileChannel out, Map<Integer, Entry> done) {
        this.out = out;
        this.done = done;
    }

    /**
     * Open the journal of a grading, reading what an earlier start of the same grading left.
     *
     * @param folder   the report folder
     * @param identity what makes this grading this one (the plan, the shard, the options that change results)
     * @return the journal
     * @throws IllegalArgumentException if the folder holds the journal of another grading
     */
    static Journal open(Path folder, String identity) {
        Path file = folder.resolve(FILE);
        String first = "{\"journal\": " + JsonValues.quote(FORMAT) + ", \"grading\": "
                + JsonValues.quote(identity) + "}\n";
        Map<Integer, Entry> done = new TreeMap<>();
        try {
            Files.createDirectories(folder);
            long keep = 0;
            if (Files.isRegularFile(file)) {
                byte[] bytes = Files.readAllBytes(file);
                String text = new String(bytes, StandardCharsets.UTF_8);
                if (!text.isEmpty() && !text.startsWith(first)) {
                    if (text.indexOf('\n') >= 0) {
                        throw new IllegalArgumentException("--out " + folder
                                + " holds the journal of another grading (other"
                                + " submissions, arenas, seeds, shard or options); give another --out, or"
                                + " delete " + file
                                + " to grade again from the start");
                    }
                    text = ""; // a torn first line: nothing was finished
                }
                keep = text.isEmpty() ? 0 : first.getBytes(StandardCharsets.UTF_8).length;
                int at = text.isEmpty() ? 0 : first.length();
                int lineNumber = 1;
                while (at < text.length()) {
                    int nl = text.indexOf('\n', at);
                    lineNumber++;
                    if (nl < 0) {
                        break; // torn: the grader was killed while writing it
                    }
                    String line = text.substring(at, nl);
                    try {
                        Map<?, ?> m = (Map<?, ?>) JsonValues.parse(line);
                        @SuppressWarnings("unchecked")
                        RunRecord r = ReportFiles.record((Map<String, Object>) m.get("run"));
                        double page = m.get("pageSeconds") instanceof Number n ? n.doubleValue() : 0;
                        done.put(((Number) m.get("index")).intValue(),
                                new Entry(r, ((Number) m.get("wallSeconds")).doubleValue(),
                                page));
                    } catch (RuntimeException e) {
                        throw new IllegalArgumentException(file + ":" + lineNumber + ": not a journal line ("
                                + e.getMessage()
                                + "); delete " + file + " to grade again from the start");
                    }
                    at = nl + 1;
                    keep += line.getBytes(StandardCharsets.UTF_8).length + 1;
                }
            }
            FileChannel ch = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
            ch.truncate(keep); // a torn last line goes
            ch.position(keep);
            if (keep == 0) {
                ch.write(ByteBuffer.wrap(first.getBytes(StandardCharsets.UTF_8)));
                ch.force(true);
            }
            return new Journal(ch, done);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot open the journal " + file + ": " + e.getMessage(), e);
        }
    }

    /** @return the runs finished before, by their index in the grading */
    Map<Integer, Entry> done() {
        return done;
    }

    /**
     * Append a finished run and force it to disk.
     *
     * @param job the run
     * @param e   what came of it
     */
    synchronized void add(GradePlan.Job job, Entry e) {
        String line = "{\"index\": " + job.index() + ", \"wallSeconds\": "
                + String.format(Locale.ROOT, "%.3f", e.wallSeconds())
                + ", \"pageSeconds\": " + String.format(Locale.ROOT, "%.3f", e.pageSeconds())
                + ", \"run\": " + ReportFiles.json(e.record()) + "}\n";
        try {
            ByteBuffer b = ByteBuffer.wrap(line.getBytes(StandardCharsets.UTF_8));
            while (b.hasRemaining()) {
                out.write(b);
            }
            out.force(false);
        } catch (IOException ex) {
            throw new UncheckedIOException("cannot write the journal: " + ex.getMessage(), ex);
        }
        done.put(job.index(), e);
    }

    /**
     * @param plan    the grading
     * @param shard   the slice made
     * @param options what else changes a run's result
     * @return the grading's identity, as the journal's first line holds it
     */
    static String identity(GradePlan plan, GradePlan.Shard shard, String options) {
        return "students=" + String.join(",", plan.students()) + "; arenas="
                + String.join(",", plan.arenas()) + "; seeds="
                + plan.seeds() + "; shard=" + shard + "; " + options;
    }

    @Override
    public void close() {
        try {
            out.close();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** @return the runs of the journal in the order of {@code jobs} (those it holds) */
    List<Entry> inOrder(List<GradePlan.Job> jobs) {
        return jobs.stream().map(j -> done.get(j.index())).toList();
    }
}
