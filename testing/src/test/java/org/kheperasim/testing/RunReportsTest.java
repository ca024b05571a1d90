package org.kheperasim.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.platform.engine.discovery.DiscoverySelectors.selectClass;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.condition.EnabledIfSystemProperty;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.reporting.ReportEntry;
import org.junit.platform.launcher.LauncherDiscoveryRequest;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;

/**
 * The extension keeps the runs of a failing test, whatever failed it, in a folder named after the test,
 * and nothing of a passing one; the runs are what the test made, ready to load again.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RunReportsTest {

    /** Set while the launcher below runs {@link StudentTests}. */
    private static final String RUNNING = "kheperasim.testing.runReportsTest";

    /**
     * A student's tests, run by the launcher below (JUnit does not run a static nested class by itself, and
     * they fail on purpose, so they run only when the launcher runs them).
     */
    @ExtendWith(RunReports.class)
    @EnabledIfSystemProperty(named = RUNNING, matches = "true")
    static class StudentTests {
        @Test
        void passes() {
            Run.of(student.Straight.class).in("lab").seconds(2).run();
        }

        @Test
        void failsAPlainAssertion() {
            Run run = Run.of(student.Straight.class).in("lab").seconds(2).run();
            Run.of("Braitenberg").in("lab").seconds(2).run();
            assertEquals(0, run.robot().finalPose().y(), "a plain JUnit assertion about a run");
        }

        @ParameterizedTest
        @ValueSource(longs = {1, 2})
        @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
        void failsOnItsOwnThread(long seed) {
            Run.of("Braitenberg").in("lab").seconds(1).seed(seed).run();
            throw new IllegalStateException("failed");
        }
    }

    @Test
    void aFailingTestsRunsAreSavedInItsFolderAndAPassingTestsAreNot(@TempDir Path dir) throws Exception {
        List<String> entries = new ArrayList<>();
        List<String> failed = new ArrayList<>();
        String before = System.getProperty(TestRuns.DIR_PROPERTY);
        System.setProperty(TestRuns.DIR_PROPERTY, dir.toString());
        System.setProperty(RUNNING, "true");
        try {
            LauncherDiscoveryRequest request = LauncherDiscoveryRequestBuilder.request().selectors(selectClass(StudentTests.class))
                    .build();
            LauncherFactory.create().execute(request, new TestExecutionListener() {
                @Override
                public void reportingEntryPublished(TestIdentifier test, ReportEntry entry) {
                    entries.addAll(entry.getKeyValuePairs().values());
                }

                @Override
                public void executionFinished(TestIdentifier test, TestExecutionResult result) {
                    if (test.isTest() && result.getStatus() == TestExecutionResult.Status.FAILED) {
                        failed.add(test.getDisplayName());
                    }
                }
            });
        } finally {
            System.clearProperty(RUNNING);
            if (before == null) {
                System.clearProperty(TestRuns.DIR_PROPERTY);
            } else {
                System.setProperty(TestRuns.DIR_PROPERTY, before);
            }
        }
        assertEquals(3, failed.size(), failed.toString());
        Path tests = dir.resolve("StudentTests");
        assertFalse(Files.exists(tests.resolve("passes")), "a passing test's runs are not written");
        Path plain = tests.resolve("failsAPlainAssertion");
        assertTrue(Files.isRegularFile(plain.resolve("lab-Straight-seed1.trace")));
        assertTrue(Files.isRegularFile(plain.resolve("lab-Braitenberg-seed1.trace")), "every run of the test");
        assertTrue(Files.isRegularFile(plain.resolve("lab.arena")));
        assertEquals(2.0, Run.load(plain.resolve("lab-Straight-seed1.trace")).duration().seconds(), 1e-9);
        assertTrue(Files.isRegularFile(tests.resolve("failsOnItsOwnThread-1").resolve("lab-Braitenberg-seed1.trace")),
                "a run made on the thread of a test's @Timeout is the test's");
        assertTrue(Files.isRegularFile(tests.resolve("failsOnItsOwnThread-2").resolve("lab-Braitenberg-seed2.trace")));
        assertEquals(4, entries.size(), entries.toString());
    }
}
