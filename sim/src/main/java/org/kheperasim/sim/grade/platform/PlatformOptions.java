package org.kheperasim.sim.grade.platform;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.kheperasim.sim.grade.GradeDeadline;
import org.kheperasim.sim.grade.ReportFiles;
import picocli.CommandLine.Option;

/**
 * {@code grade}'s options for the learning platforms ({@code --format}, {@code --hidden}) and for
 * grading inside a platform's time ({@code --deadline}); a picocli mixin.
 */
public final class PlatformOptions {
    @Option(names = "--format", paramLabel = "PLATFORM", split = ",",
            description = "also write each submission's result for these platforms: gradescope,"
                    + " prairielearn, classroom, codegrade (comma separated or repeated), in DIR/PLATFORM/STUDENT/; see"
                    + " docs/autograding.md")
    List<String> formats = new ArrayList<>();

    @Option(names = "--hidden", arity = "1..*", paramLabel = "ARENA",
            description = "arenas of --arenas whose runs the students must not see: hidden in the platforms' results"
                    + " (Gradescope: visibility hidden; elsewhere only their points shown)")
    List<String> hidden = new ArrayList<>();

    @Option(names = "--deadline", paramLabel = "DURATION",
            description = "the grading's own real-time limit (e.g. 9m, 540s): when it passes the runs going"
                    + " are stopped and the report holds the runs made before it, each with its points; keep it below"
                    + " the platform's timeout")
    String deadline;

    /** @return the deadline in seconds, or null for none @throws IllegalArgumentException for a bad one */
    public Double deadlineSeconds() {
        return deadline == null ? null : GradeDeadline.parse(deadline);
    }

    /** @return the formats asked for, checked (before any run is made) */
    public Set<PlatformFormat> formats() {
        Set<PlatformFormat> f = PlatformFormat.parse(formats);
        if (!hidden.isEmpty() && f.isEmpty()) {
            throw new IllegalArgumentException("--hidden " + String.join(" ", hidden)
                    + ": hidden from what? give --format"
                    + " gradescope (or prairielearn, classroom, codegrade) too");
        }
        return f;
    }

    /** @param arenas the arenas graded @throws IllegalArgumentException for a hidden arena that is not graded */
    public void check(List<String> arenas) {
        for (String h : hidden) {
            if (!arenas.contains(h)) {
                throw new IllegalArgumentException("--hidden " + h + ": not one of --arenas ("
                        + String.join(", ", arenas)
                        + "); give each hidden arena in --arenas too, written the same way");
            }
        }
    }

    /**
     * Writes the platforms' files of a grading.
     *
     * @param report           the grading's report
     * @param out              its folder
     * @param executionSeconds the grading's real seconds
     * @return the files written
     */
    public List<Path> write(ReportFiles.Report report, Path out, long executionSeconds) {
        Set<PlatformFormat> f = formats();
        if (f.isEmpty()) {
            return List.of();
        }
        return PlatformFormat.writeAll(GradingTests.of(report, new LinkedHashSet<>(hidden)), f, out, executionSeconds);
    }
}
