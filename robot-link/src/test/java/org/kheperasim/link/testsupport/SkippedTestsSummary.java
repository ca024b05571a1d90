package org.kheperasim.link.testsupport;

import java.util.ArrayList;
import java.util.List;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;

/**
 * Says out loud, at the end of a module's tests, which tests were skipped and why (a tool or a
 * folder this machine lacks: socat, Xvfb, Chromium, bubblewrap, Slurm, the real WSU world files),
 * so that a green build that did not run them cannot pass unnoticed. Each line gives the skip's own
 * reason, which names what it needs; the count is Maven's (a class skipped as a whole counts each
 * of its tests). Registered through {@code META-INF/services}; shared with the simulator's tests
 * through robot-link's test jar.
 */
public final class SkippedTestsSummary implements TestExecutionListener {
    private final List<String> skipped = new ArrayList<>();
    private int tests;
    private TestPlan plan;

    @Override
    public synchronized void testPlanExecutionStarted(TestPlan testPlan) {
        plan = testPlan;
    }

    @Override
    public synchronized void executionSkipped(TestIdentifier test, String reason) {
        note(test, reason);
    }

    @Override
    public synchronized void executionFinished(TestIdentifier test, TestExecutionResult result) {
        if (result.getStatus() == TestExecutionResult.Status.ABORTED) {
            note(test, result.getThrowable().map(Throwable::getMessage).orElse("aborted"));
        }
    }

    /** A skipped container counts as the tests in it, as Maven counts them. */
    private void note(TestIdentifier test, String reason) {
        int n = test.isTest() || plan == null ? 1
                : (int) StrictMath.max(1, plan.getDescendants(test).stream().filter(TestIdentifier::isTest).count());
        tests += n;
        skipped.add(test.getDisplayName() + (n > 1 ? " (" + n + " tests)" : "") + ": " + reason);
    }

    @Override
    public synchronized void testPlanExecutionFinished(TestPlan testPlan) {
        if (skipped.isEmpty()) {
            return;
        }
        String rule = "*".repeat(100);
        StringBuilder b = new StringBuilder("\n").append(rule).append('\n');
        b.append("* SKIPPED ").append(tests).append(" test(s), each for the reason given (what this machine lacks).")
                .append(" With CI=true they\n");
        b.append("* must run, and a missing tool fails the build; README.md says what each kind of test needs.\n");
        for (String s : skipped) {
            b.append("*   ").append(s).append('\n');
        }
        b.append(rule).append('\n');
        System.out.print(b);
    }
}
