package org.kheperasim.testing;

import java.lang.reflect.Method;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * The runs the current test made, and the folder their files go to. {@link RunReports} opens one per
 * test; without it, a run's files go to a folder named after the test method found on the stack. The
 * current test is inherited by threads the test starts (JUnit's {@code @Timeout} runs a test on its own
 * thread), so a run made there is still the test's.
 */
final class TestRuns {
    /** The system property that moves the runs' folder (default {@code target/kheperasim-runs}). */
    static final String DIR_PROPERTY = "kheperasim.runs.dir";
    private static final InheritableThreadLocal<TestRuns> CURRENT = new InheritableThreadLocal<>();

    private final Path folder;
    private final List<Run> runs = new ArrayList<>();

    private TestRuns(Path folder) {
        this.folder = folder;
    }

    /** @return the folder every test's runs go under */
    static Path base() {
        return Path.of(System.getProperty(DIR_PROPERTY, "target/kheperasim-runs"));
    }

    /**
     * A test starts.
     *
     * @param testClass its class's simple name
     * @param test its method's name, with the invocation's index for a repeated or parameterized one
     * @return its runs
     */
    static TestRuns enter(String testClass, String test) {
        TestRuns t = new TestRuns(base().resolve(safe(testClass)).resolve(safe(test)));
        CURRENT.set(t);
        return t;
    }

    /** The test has ended. */
    static void leave() {
        CURRENT.remove();
    }

    /** @param run a run the current test made */
    static void made(Run run) {
        TestRuns t = CURRENT.get();
        if (t != null) {
            synchronized (t) {
                t.runs.add(run);
            }
        }
    }

    /** @return the runs this test made, in order */
    synchronized List<Run> runs() {
        return List.copyOf(runs);
    }

    /** @return the folder this test's runs go to */
    Path folder() {
        return folder;
    }

    /**
     * @return the current test's folder: the one {@link RunReports} opened, else one named after the test
     *     method that called the API (found on the stack), else the base folder
     */
    static Path folderNow() {
        TestRuns t = CURRENT.get();
        if (t != null) {
            return t.folder;
        }
        return callingTest()
                .map(f -> base().resolve(safe(f.getDeclaringClass().getSimpleName())).resolve(safe(f.getMethodName())))
                .orElse(base());
    }

    /** The first frame on the stack outside this library that is a JUnit test method. */
    private static Optional<StackWalker.StackFrame> callingTest() {
        CodeSource ours = TestRuns.class.getProtectionDomain().getCodeSource();
        return StackWalker.getInstance(StackWalker.Option.RETAIN_CLASS_REFERENCE).walk(frames -> frames
                .filter(f -> ours == null || !ours.equals(f.getDeclaringClass().getProtectionDomain().getCodeSource()))
                .filter(TestRuns::isTestMethod)
                .findFirst());
    }

    private static boolean isTestMethod(StackWalker.StackFrame f) {
        for (Method m : f.getDeclaringClass().getDeclaredMethods()) {
            if (m.getName().equals(f.getMethodName())) {
                for (java.lang.annotation.Annotation a : m.getAnnotations()) {
                    String n = a.annotationType().getName();
                    if (n.startsWith("org.junit.jupiter.") && n.endsWith("Test")) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /** A name as a folder's: letters, digits and {@code ._-} only. */
    static String safe(String name) {
        String s = name.replaceAll("[^A-Za-z0-9._-]+", "_");
        return s.length() > 80 ? s.substring(0, 80) : s;
    }
}
