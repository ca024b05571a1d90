package org.kheperasim.sim.grade;

/**
 * One graded run as the report holds it: everything here is the same however and wherever the
 * run was made (wall-clock times are kept apart, in {@code timings.csv}), so sharded and unsharded
 * gradings give identical reports.
 *
 * @param student          the submission's folder name
 * @param arena            the arena as given on the command line
 * @param seed             the run's seed
 * @param status           how it ended
 * @param points           points earned (0 when it did not run)
 * @param max              points available in the arena
 * @param percent          points as a percentage of max, 0..100
 * @param simulatedSeconds simulated time reached, s
 * @param controller       the controller class that ran (empty when none)
 * @param detail           the failure or the score's details, one line
 * @param picture          the trajectory picture, relative to the report folder (empty when none)
 * @param madeIn           how the run was made: {@link #SANDBOX}, {@link #NO_SANDBOX}, or empty when it was not
 *                         (it did not compile)
 * @param page             the run's web page, which replays it in a browser, relative to the report folder (empty
 *                         when there is none: the run left nothing to replay)
 * @param rerun            when the run was made again (its first making's result differed from its replay): what
 *                         differed the first time, one line; empty when it was made once
 */
public record RunRecord(String student, String arena, long seed, RunStatus status, double points, double max,
        double percent, double simulatedSeconds, String controller, String detail, String picture, String madeIn,
        String page, String rerun) {
    /** Made in the operating-system sandbox (docs/grading.md, "The sandbox"). */
    public static final String SANDBOX = "sandbox";
    /** Made without it ({@code grade --no-sandbox}). */
    public static final String NO_SANDBOX = "no_sandbox";

    /** Keeps the detail to one line; rounds the numbers as the report writes them (2 decimals; 3 for seconds). */
    public RunRecord {
        points = ReportFiles.round2(points);
        max = ReportFiles.round2(max);
        percent = ReportFiles.round2(percent);
        simulatedSeconds = StrictMath.rint(simulatedSeconds * 1000) / 1000;
        detail = detail == null ? "" : detail.replaceAll("[\\r\\n]+", " ").strip();
        controller = controller == null ? "" : controller;
        picture = picture == null ? "" : picture;
        madeIn = madeIn == null ? "" : madeIn;
        page = page == null ? "" : page;
        rerun = rerun == null ? "" : rerun.replaceAll("[\\r\\n]+", " ").strip();
    }

    /** A run made once. */
    public RunRecord(String student, String arena, long seed, RunStatus status, double points,
            double max, double percent,
            double simulatedSeconds, String controller, String detail, String picture, String madeIn, String page) {
        this(student, arena, seed, status, points, max, percent, simulatedSeconds, controller, detail, picture,
                madeIn, page, "");
    }

    /** A run without a page (yet). */
    public RunRecord(String student, String arena, long seed, RunStatus status, double points,
            double max, double percent,
            double simulatedSeconds, String controller, String detail, String picture, String madeIn) {
        this(student, arena, seed, status, points, max, percent, simulatedSeconds, controller, detail, picture,
                madeIn, "", "");
    }

    /** @param picture the trajectory picture @return this run with it */
    RunRecord withPicture(String picture) {
        return new RunRecord(student, arena, seed, status, points, max, percent, simulatedSeconds, controller,
                detail, picture,
                madeIn, page, rerun);
    }

    /** @param page the run's web page @return this run with it */
    RunRecord withPage(String page) {
        return new RunRecord(student, arena, seed, status, points, max, percent, simulatedSeconds, controller,
                detail, picture,
                madeIn, page, rerun);
    }

    /** @param firstDifference what differed from the replay the first time @return this run, made again */
    RunRecord withRerun(String firstDifference) {
        return new RunRecord(student, arena, seed, status, points, max, percent, simulatedSeconds, controller,
                detail, picture,
                madeIn, page, firstDifference);
    }

    /** @return true when the run was made again */
    public boolean madeAgain() {
        return !rerun.isEmpty();
    }
}
