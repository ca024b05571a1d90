package org.kheperasim.sim.grade;

import java.io.PrintStream;
import java.util.Locale;
import org.kheperasim.sim.text.Shown;

/**
 * The progress of a grading on standard error: on a terminal a bar redrawn in place, elsewhere (a
 * batch job's log) one line per run; both with an estimate of the time left, from the mean wall
 * time per finished run and the number of runs going at once.
 */
final class Progress {
    private final PrintStream out;
    private final int total;
    private final boolean terminal;
    private final long start = System.nanoTime();
    private int done;
    /** Runs a journal held from an earlier start: done, but not timed here. */
    private int skipped;
    private int failed;

    Progress(PrintStream out, int total, boolean terminal) {
        this.out = out;
        this.total = total;
        this.terminal = terminal;
    }

    /** @param runs runs a journal held from an earlier start: counted as done, not timed */
    synchronized void skip(int runs) {
        done += runs;
        skipped = runs;
        if (runs > 0) {
            out.println(String.format(Locale.ROOT, "%d of %d runs were made before (the journal holds them); making the"
                    + " other %d", runs, total, total - runs));
        }
    }

    synchronized void finished(GradePlan.Job job, RunRecord r) {
        done++;
        if (r.status() != RunStatus.OK) {
            failed++;
        }
        double elapsed = (System.nanoTime() - start) / 1e9;
        double left = done == skipped ? 0 : elapsed / (done - skipped) * (total - done);
        if (terminal) {
            int width = 30;
            int filled = total == 0 ? width : done * width / total;
            out.print(String.format(Locale.ROOT, "\r[%s%s] %d/%d runs, %d not ok, %s elapsed, about %s left   ",
                    "#".repeat(filled), "-".repeat(width - filled), done, total, failed, clock(elapsed), clock(left)));
            if (done == total) {
                out.println();
            }
        } else {
            out.println(String.format(Locale.ROOT,
                    "[%d/%d] %s %s seed %d: %s %s%%; %s elapsed, about %s left", done, total,
                    Shown.line(job.student()), Shown.line(ReportFiles.arenaLabel(job.arena())), job.seed(),
                    r.status().label(),
                    ReportFiles.num(r.percent()), clock(elapsed), clock(left)));
        }
        out.flush();
    }

    static String clock(double seconds) {
        long s = StrictMath.round(seconds);
        return s >= 3600 ? String.format(Locale.ROOT, "%d:%02d:%02d", s / 3600, s / 60 % 60, s % 60)
                : String.format(Locale.ROOT, "%d:%02d", s / 60, s % 60);
    }
}
