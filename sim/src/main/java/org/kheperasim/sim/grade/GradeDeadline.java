package org.kheperasim.sim.grade;

import java.util.Locale;
import java.util.Set;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.kheperasim.sim.arena.Arena;

/**
 * A grading's own deadline ({@code grade --deadline 9m}), kept below a platform's timeout (Gradescope
 * gives a submission that outlives its timeout a 0 and no tests): when it passes, the runs going are
 * killed, no run is started, and the report holds the runs finished before it, each with its points;
 * a run not made counts 0 and says why ({@link #notMade}). A killed run goes to no journal, so the same
 * grading started again makes it.
 */
public final class GradeDeadline {
    /** How the detail of a run not made before the deadline starts (the platforms' writers look for it). */
    public static final String NOT_MADE = "not made: the grading's deadline";
    private static final Pattern DURATION = Pattern.compile("(\\d{1,7}(?:\\.\\d{1,3})?)\\s*(ms|s|m|min|h)?");
    /** How often the watchdog kills again what started after the deadline, ms. */
    private static final long REKILL_MILLIS = 50;

    private GradeDeadline() {
    }

    /**
     * @param text a duration: {@code 540}, {@code 540s}, {@code 9m}, {@code 1.5h}, {@code 800ms}
     * @return it in seconds
     * @throws IllegalArgumentException naming the value and the forms taken
     */
    public static double parse(String text) {
        Matcher m = DURATION.matcher(text == null ? "" : text.strip().toLowerCase(Locale.ROOT));
        if (!m.matches() || Double.parseDouble(m.group(1)) <= 0) {
            throw new IllegalArgumentException("--deadline '" + text
                    + "': give a duration above 0 such as 540, 540s, 9m or"
                    + " 1h (real time for the whole grading; keep it a minute below the platform's timeout)");
        }
        double v = Double.parseDouble(m.group(1));
        String unit = m.group(2) == null ? "s" : m.group(2);
        return switch (unit) {
            case "ms" -> v / 1000;
            case "m", "min" -> v * 60;
            case "h" -> v * 3600;
            default -> v;
        };
    }

    /** @param seconds a deadline, s @return how the report names it, e.g. {@code 9 min} or {@code 45 s} */
    public static String shown(double seconds) {
        return seconds >= 60 && seconds % 60 == 0 ? String.format(Locale.ROOT, "%d min", (long) (seconds / 60))
                : ReportFiles.num(seconds) + " s";
    }

    /**
     * Starts the watchdog: at the deadline it sets {@code stopping} and kills every process going, again
     * and again until {@code done} is set (a worker that started in the meantime is killed too).
     *
     * @param endNanos the deadline, {@link System#nanoTime} scale
     * @param stopping set when the deadline passes (the grader then starts nothing and journals nothing)
     * @param passed   set when the deadline passed, for the report
     * @param done     set by the grader once every run has come back
     * @param running  the processes going
     * @return the watchdog's thread (a daemon)
     */
    static Thread watch(long endNanos, AtomicBoolean stopping, AtomicBoolean passed, AtomicBoolean done,
            Set<Process> running) {
        Thread t = new Thread(() -> {
            try {
                long left;
                while (!done.get() && (left = endNanos - System.nanoTime()) > 0) {
                    Thread.sleep(StrictMath.max(1, StrictMath.min(left / 1_000_000, 200)));
                }
                if (done.get()) {
                    return;
                }
                passed.set(true);
                stopping.set(true);
                while (!done.get()) {
                    running.forEach(ChildRun::kill);
                    Thread.sleep(REKILL_MILLIS);
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "grade-deadline");
        t.setDaemon(true);
        t.start();
        return t;
    }

    /**
     * @param job      a run the grading did not make before its deadline
     * @param arena    its arena
     * @param seconds  the deadline, s
     * @return its record: no points, out of the arena's, status {@code error} with a detail that says so
     */
    static RunRecord notMade(GradePlan.Job job, Arena arena, double seconds) {
        return new RunRecord(job.student(), job.arena(), job.seed(), RunStatus.ERROR, 0,
                arena.assignment().maxPoints(), 0, 0,
                "", NOT_MADE + " (--deadline " + shown(seconds)
                        + ") passed first; it counts 0 here, the runs made before"
                + " it keep their points; grade again on the same --out to make it", "", "");
    }

    /** @param r a run @return true when it was not made because the grading's deadline passed */
    public static boolean notMade(RunRecord r) {
        return r.status() == RunStatus.ERROR && r.detail().startsWith(NOT_MADE);
    }
}
