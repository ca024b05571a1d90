package org.kheperasim.sim.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.kheperasim.sim.files.AtomicFiles;

/**
 * The grader's guard for a run whose own result differed from its replay although its JVM ended
 * normally ({@link Verdict.Judged#diverged}): it is made again, once, and only a difference that
 * repeats is named ({@link RunStatus#DIVERGED}). An honest run replays exactly (ReplayExactnessTest
 * holds the simulator to it), so a difference that does not repeat says nothing about the student;
 * the report counts such reruns and says what differed the first time. The first making's command
 * log is kept beside the second's ({@code *.first.log.gz}) while the traces are kept, for a bug report.
 */
final class Rerun {
    /** Makes the run (again). */
    @FunctionalInterface
    interface Making {
        ChildRun.Outcome make() throws IOException;
    }

    private Rerun() {
    }

    /**
     * @param first the first making's outcome
     * @param again makes the run again
     * @return the outcome to report: the first when it did not differ from its replay, else the second's, which
     *     says what differed the first time
     * @throws IOException if the run cannot be made again
     */
    static ChildRun.Outcome guard(ChildRun.Outcome first, Making again) throws IOException {
        if (first.diverged() == null) {
            return first;
        }
        if (first.log() != null && Files.isRegularFile(first.log())) {
            AtomicFiles.rename(first.log(), firstLog(first.log()));
        }
        return combine(first, again.make());
    }

    /**
     * @param first  a making whose result differed from its replay
     * @param second the making again
     * @return the second, with what differed the first time; when it differs too, its reason says it repeated
     */
    static ChildRun.Outcome combine(ChildRun.Outcome first, ChildRun.Outcome second) {
        RunRecord r = second.record().withRerun(first.diverged());
        if (second.diverged() != null) {
            r = new RunRecord(r.student(), r.arena(), r.seed(), r.status(), r.points(), r.max(), r.percent(),
                    r.simulatedSeconds(),
                    r.controller(), "in both makings of the run: " + r.detail(), r.picture(), r.madeIn(),
                    r.page(), r.rerun());
        }
        return new ChildRun.Outcome(r, first.wallSeconds() + second.wallSeconds(), second.trace(),
                second.log(), second.page(),
                second.tape(), second.diverged());
    }

    /** @param log a run's command log @return where the log of its first making is kept when it was made again */
    static Path firstLog(Path log) {
        return log.resolveSibling(log.getFileName().toString().replaceFirst("\\.log\\.gz$", "") + ".first.log.gz");
    }
}
