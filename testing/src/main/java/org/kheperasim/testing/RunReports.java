package org.kheperasim.testing;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.AfterTestExecutionCallback;
import org.junit.jupiter.api.extension.BeforeEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * A JUnit 5 extension that keeps the runs of a failing test for the student to watch: every run the test
 * made is saved, trace and arena, under {@code target/kheperasim-runs/TestClass/testMethod/} (beside
 * {@code target/surefire-reports}), whatever made the test fail: an assertion of this library, a plain
 * {@code assertEquals}, an exception. A trace opens in the simulator's window (File &gt; Open recording);
 * the {@code .txt} file beside it has the command that makes the run again.
 *
 * <pre>{@code
 * @ExtendWith(RunReports.class)
 * class MyControllerTest { ... }
 * }</pre>
 *
 * <p>Without it, a failing assertion of this library still saves the run it was about, in a folder named
 * after the test method. The system property {@code kheperasim.runs.dir} moves the folder. Runs of passing
 * tests are not written. Each saved run is also published as a JUnit report entry ({@code kheperasim.trace}).
 */
public final class RunReports implements BeforeEachCallback, AfterTestExecutionCallback, AfterEachCallback {
    private static final ExtensionContext.Namespace NAMESPACE = ExtensionContext.Namespace.create(RunReports.class);
    private static final Pattern INVOCATION = Pattern.compile("#(\\d+)]$");

    /** Made by JUnit ({@code @ExtendWith(RunReports.class)}). */
    public RunReports() {
    }

    /**
     * A test starts: the runs it makes from now on are its own.
     *
     * @param context the test
     */
    @Override
    public void beforeEach(ExtensionContext context) {
        String test = context.getRequiredTestMethod().getName();
        Matcher m = INVOCATION.matcher(context.getUniqueId());
        if (m.find()) {
            test += "-" + m.group(1);
        }
        context.getStore(NAMESPACE)
                .put(TestRuns.class, TestRuns.enter(context.getRequiredTestClass().getSimpleName(), test));
    }

    /**
     * The test has run: if it failed, save its runs.
     *
     * @param context the test
     */
    @Override
    public void afterTestExecution(ExtensionContext context) {
        TestRuns runs = context.getStore(NAMESPACE).get(TestRuns.class, TestRuns.class);
        if (runs == null || context.getExecutionException().isEmpty() || runs.runs().isEmpty()) {
            return;
        }
        List<String> saved = new ArrayList<>();
        for (Run run : runs.runs()) {
            Path trace = run.saveTo(runs.folder());
            saved.add(RunSpec.shown(trace));
            context.publishReportEntry("kheperasim.trace", RunSpec.shown(trace));
        }
        // A failed assertion of this library already names its run's trace; any other failure gets the line here.
        String failure = String.valueOf(context.getExecutionException().get().getMessage());
        if (!failure.contains(Failure.TRACE_LINE)) {
            System.err.println("kheperasim: " + context.getDisplayName() + " failed; its run"
                    + (saved.size() == 1 ? " is"
                    : "s are") + " saved to watch in the simulator's window (File > Open recording): "
                            + String.join(", ", saved));
        }
    }

    /**
     * The test has ended.
     *
     * @param context the test
     */
    @Override
    public void afterEach(ExtensionContext context) {
        TestRuns.leave();
    }
}
