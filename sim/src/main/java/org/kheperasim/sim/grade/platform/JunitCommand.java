package org.kheperasim.sim.grade.platform;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code grade junit}: a JUnit XML report folder (the course's hidden tests) as the platforms' results. */
@Command(name = "junit", mixinStandardHelpOptions = true,
        description = "Write a folder of JUnit XML reports (target/surefire-reports of the course's tests over one"
                + " student's copy) as the platforms' results: a test per test case, worth --points when it passed. No"
                + " report, or no test case, is 'not gradable'. See docs/autograding.md.")
public final class JunitCommand implements Callable<Integer> {
    @Option(names = "--reports", paramLabel = "DIR", required = true, description = "the JUnit XML reports' folder")
    Path reports;

    @Option(names = "--format", paramLabel = "PLATFORM", split = ",", required = true,
            description = "gradescope, prairielearn, classroom, codegrade (comma separated or repeated)")
    List<String> formats = new ArrayList<>();

    @Option(names = "--out", paramLabel = "DIR", defaultValue = "grade-report", description = "where the results go, in"
            + " DIR/PLATFORM/STUDENT/ (default: ${DEFAULT-VALUE})")
    Path out;

    @Option(names = "--student", paramLabel = "NAME", defaultValue = "submission", description = "the submission's name"
            + " (default: ${DEFAULT-VALUE})")
    String student;

    @Option(names = "--points", paramLabel = "P", defaultValue = "1", description = "each test case's points (default:"
            + " ${DEFAULT-VALUE})")
    double points;

    @Option(names = "--hidden", description = "the students must not see the tests (Gradescope: visibility hidden;"
            + " elsewhere only their points shown)")
    boolean hidden;

    @Override
    public Integer call() {
        if (!(points > 0) || Double.isInfinite(points)) {
            throw new IllegalArgumentException("--points " + points
                    + ": give each test case's points, above 0, e.g. --points 2");
        }
        PlatformResult r = JunitReports.read(reports, student, points, hidden);
        for (Path p : PlatformFormat.writeAll(List.of(r), PlatformFormat.parse(formats), out, 0)) {
            System.out.println("wrote " + p);
        }
        return 0;
    }
}
