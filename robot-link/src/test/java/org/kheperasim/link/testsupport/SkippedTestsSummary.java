package org.kheperasim.link.testsupport;

import java.util.ArrayList;
import java.util.List;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;

/**
 * Says out loud, at the end of a module's tests, which tests were skipped and why (socat or Xvfb
 * missing on a student's laptop), so that a green build that did not run the pty or window tests
 * cannot pass unnoticed. Registered through {@code META-INF/services}; shared with the simulator's
 * tests through robot-link's test jar.
 */
public final class SkippedTestsSummary implements TestExecutionListener {
    private final List<String> skipped = new ArrayList<>();

    @Override
    public synchronized void executionSkipped(TestIdentifier test, String reason) {
        skipped.add(test.getDisplayName() + ": " + reason);
    }

    @Override
    public synchronized void executionFinished(TestIdentifier test, TestExecutionResult result) {
        if (result.getStatus() == TestExecutionResult.Status.ABORTED) {
            skipped.add(test.getDisplayName() + ": " + result.getThrowable().map(Throwable::getMessage).orElse("aborted"));
        }
    }

    @Override
    public synchronized void testPlanExecutionFinished(TestPlan plan) {
        if (skipped.isEmpty()) {
            return;
        }
        String rule = "*".repeat(100);
        StringBuilder b = new StringBuilder("\n").append(rule).append('\n');
        b.append("* SKIPPED ").append(skipped.size()).append(" test(s): they need tools this machine lacks. They run in CI (CI=true),\n");
        b.append("* where a missing tool fails the build. Install them with: apt-get install -y socat xvfb xauth\n");
        for (String s : skipped) {
            b.append("*   ").append(s).append('\n');
        }
        b.append(rule).append('\n');
        System.out.print(b);
    }
}
