package org.kheperasim.link.testsupport;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.TestSource;
import org.junit.platform.engine.support.descriptor.ClassSource;
import org.junit.platform.engine.support.descriptor.MethodSource;
import org.junit.platform.launcher.LauncherSession;
import org.junit.platform.launcher.LauncherSessionListener;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;

/**
 * Says out loud, at the end of a module's tests, which tests were skipped and why (a tool or a
 * folder this machine lacks: socat, Xvfb, Chromium, bubblewrap, Slurm, the real WSU world files, the
 * optional WSU course corpus), so that a green build that did not run them cannot pass unnoticed.
 * Each line gives the skip's own reason, which names what it needs; the count is Maven's (a class
 * skipped as a whole counts each of its tests).
 *
 * <p>The tests of a module run in several JVMs at once (surefire's {@code forkCount}), each handed
 * one class at a time. So each JVM writes its skips to a ledger under {@code target/skipped-tests/}
 * when its launcher session closes, and the last JVM of that Maven run to close prints one box for
 * the whole module. Registered through {@code META-INF/services} as both listeners; shared with the
 * simulator's tests through robot-link's test jar.
 */
public final class SkippedTestsSummary implements TestExecutionListener, LauncherSessionListener {
    /** What this JVM skipped: one line per skip, {@code count TAB class TAB name TAB reason}. */
    private static final List<String> SKIPPED = new ArrayList<>();
    private static Path ledger;
    private static TestPlan plan;

    @Override
    public void launcherSessionOpened(LauncherSession session) {
        synchronized (SKIPPED) {
            try {
                ledger = Ledger.open();
            } catch (IOException | UncheckedIOException e) {
                ledger = null;
            }
        }
    }

    @Override
    public void testPlanExecutionStarted(TestPlan testPlan) {
        synchronized (SKIPPED) {
            plan = testPlan;
        }
    }

    @Override
    public void executionSkipped(TestIdentifier test, String reason) {
        note(test, reason);
    }

    @Override
    public void executionFinished(TestIdentifier test, TestExecutionResult result) {
        if (result.getStatus() == TestExecutionResult.Status.ABORTED) {
            note(test, result.getThrowable().map(Throwable::getMessage).orElse("aborted"));
        }
    }

    /** A skipped container counts as the tests in it, as Maven counts them. */
    private static void note(TestIdentifier test, String reason) {
        synchronized (SKIPPED) {
            int n = test.isTest() || plan == null ? 1
                    : (int) StrictMath.max(1, plan.getDescendants(test).stream().filter(TestIdentifier::isTest).count());
            String why = (reason == null ? "no reason given" : reason).replaceFirst("^Assumption failed: ", "")
                    .replaceAll("\\s+", " ").strip();
            SKIPPED.add(n + "\t" + className(test) + "\t" + name(test, n) + "\t" + why);
        }
    }

    /** @return the simple name of the test's class, or its display name */
    private static String className(TestIdentifier test) {
        Optional<TestSource> source = test.getSource();
        String c = source.isPresent() && source.get() instanceof MethodSource m ? m.getClassName()
                : source.isPresent() && source.get() instanceof ClassSource k ? k.getClassName() : test.getDisplayName();
        return c.substring(c.lastIndexOf('.') + 1);
    }

    /** @return Class.method(), or Class (n tests) for a class skipped whole */
    private static String name(TestIdentifier test, int n) {
        Optional<TestSource> source = test.getSource();
        if (source.isPresent() && source.get() instanceof MethodSource m) {
            String simple = m.getClassName().substring(m.getClassName().lastIndexOf('.') + 1);
            String invocation = test.getDisplayName().startsWith("[") ? " " + test.getDisplayName() : "";
            return simple + "." + m.getMethodName() + "()" + invocation;
        }
        if (source.isPresent() && source.get() instanceof ClassSource c) {
            return c.getClassName().substring(c.getClassName().lastIndexOf('.') + 1) + (n > 1 ? " (" + n + " tests)" : "");
        }
        return test.getDisplayName() + (n > 1 ? " (" + n + " tests)" : "");
    }

    @Override
    public void launcherSessionClosed(LauncherSession session) {
        List<String> all;
        synchronized (SKIPPED) {
            try {
                all = ledger == null ? List.copyOf(SKIPPED) : Ledger.close(ledger, SKIPPED);
            } catch (IOException | UncheckedIOException e) {
                all = List.copyOf(SKIPPED);
            }
        }
        if (all != null && !all.isEmpty()) {
            System.out.print(box(all));
            System.out.flush();
        }
    }

    /**
     * @param lines every skip, as in {@link #SKIPPED}
     * @return the box: the count, then each reason with the tests it skipped, by class
     */
    static String box(List<String> lines) {
        int tests = 0;
        // reason -> class -> [tests, names]
        Map<String, Map<String, List<String>>> byReason = new TreeMap<>();
        Map<String, Integer> counts = new TreeMap<>();
        for (String l : lines) {
            String[] f = l.split("\t", 4);
            int n = Integer.parseInt(f[0]);
            tests += n;
            byReason.computeIfAbsent(f[3], r -> new TreeMap<>()).computeIfAbsent(f[1], c -> new ArrayList<>()).add(f[2]);
            counts.merge(f[3] + "\t" + f[1], n, Integer::sum);
            counts.merge(f[3], n, Integer::sum);
        }
        String rule = "*".repeat(100);
        String module = Path.of("").toAbsolutePath().getFileName().toString();
        StringBuilder b = new StringBuilder("\n").append(rule).append('\n');
        b.append("* SKIPPED ").append(tests).append(" test(s) in ").append(module)
                .append(" (Maven's count), for these reasons (what this machine lacks):\n");
        for (Map.Entry<String, Map<String, List<String>>> r : byReason.entrySet()) {
            b.append("*   ").append(r.getKey()).append('\n');
            List<String> classes = new ArrayList<>();
            for (Map.Entry<String, List<String>> c : r.getValue().entrySet()) {
                int n = counts.get(r.getKey() + "\t" + c.getKey());
                classes.add(c.getValue().size() == 1 ? c.getValue().get(0) : c.getKey() + " (" + n + " tests)");
            }
            String line = "*     " + counts.get(r.getKey()) + (counts.get(r.getKey()) == 1 ? " test: " : " tests: ");
            for (int i = 0; i < classes.size(); i++) {
                String item = classes.get(i) + (i + 1 < classes.size() ? "," : "");
                if (line.length() + 1 + item.length() > 100 && !line.isBlank()) {
                    b.append(line.stripTrailing()).append('\n');
                    line = "*       ";
                }
                line += item + " ";
            }
            b.append(line.stripTrailing()).append('\n');
        }
        b.append("* README.md (\"Skipped tests\") says what each kind needs. With CI=true a missing tool or missing WSU world")
                .append(" files\n* fail the build instead; the WSU course corpus (-Dkheperasim.wsuCorpus=DIR) is optional everywhere.\n");
        return b.append(rule).append('\n').toString();
    }

    /**
     * The skips of one Maven run's test JVMs of one module, in {@code target/skipped-tests/RUN/}: a
     * {@code PID.open} file while a JVM runs tests, a {@code PID.skips} file once it has finished.
     */
    static final class Ledger {
        private Ledger() {
        }

        /** @return this JVM's ledger folder, its {@code .open} file made; null outside Maven */
        static Path open() throws IOException {
            String run = mavenRun();
            if (run == null) {
                return null;
            }
            Path root = Path.of("target", "skipped-tests");
            Files.createDirectories(root);
            Path dir = root.resolve(run);
            try (FileChannel lock = FileChannel.open(root.resolve("lock"), StandardOpenOption.CREATE, StandardOpenOption.WRITE);
                    FileLock held = lock.lock()) {
                // Ledgers of earlier runs: gone (they are complete or were left by a crash).
                try (Stream<Path> old = Files.list(root)) {
                    for (Path p : old.filter(Files::isDirectory).filter(p -> !p.equals(dir)).toList()) {
                        deleteFolder(p);
                    }
                }
                Files.createDirectories(dir);
                Files.writeString(dir.resolve(ProcessHandle.current().pid() + ".open"), "");
            }
            return dir;
        }

        /** Records this JVM's skips; @return every JVM's, when this is the last to finish, else null */
        static List<String> close(Path dir, List<String> mine) throws IOException {
            Path root = dir.getParent();
            try (FileChannel lock = FileChannel.open(root.resolve("lock"), StandardOpenOption.CREATE, StandardOpenOption.WRITE);
                    FileLock held = lock.lock()) {
                long pid = ProcessHandle.current().pid();
                Files.write(dir.resolve(pid + ".skips"), mine, StandardCharsets.UTF_8);
                Files.deleteIfExists(dir.resolve(pid + ".open"));
                List<Path> files;
                try (Stream<Path> s = Files.list(dir)) {
                    files = s.sorted().toList();
                }
                if (files.stream().anyMatch(p -> p.getFileName().toString().endsWith(".open"))) {
                    return null;
                }
                List<String> all = new ArrayList<>();
                for (Path p : files) {
                    all.addAll(Files.readAllLines(p, StandardCharsets.UTF_8).stream().filter(l -> !l.isBlank()).toList());
                }
                return all;
            }
        }

        /**
         * @return the Maven run and the plugin these tests run under (the Maven JVM's pid and start, and
         *     surefire or failsafe, from the POM's {@code kheperasim.testPlugin}), or null outside Maven
         */
        static String mavenRun() {
            String plugin = System.getProperty("kheperasim.testPlugin");
            if (plugin == null) {
                return null;
            }
            Optional<ProcessHandle> p = ProcessHandle.current().parent();
            for (int up = 0; up < 4 && p.isPresent(); up++) {
                ProcessHandle h = p.get();
                String cmd = h.info().commandLine().orElse("");
                if (cmd.contains("plexus-classworlds") || cmd.contains("org.codehaus.plexus.classworlds.launcher.Launcher")) {
                    return plugin + "-" + h.pid() + "-" + h.info().startInstant().map(i -> i.toEpochMilli()).orElse(0L);
                }
                p = h.parent();
            }
            return null;
        }

        private static void deleteFolder(Path p) throws IOException {
            try (Stream<Path> all = Files.walk(p)) {
                for (Path f : all.sorted(Comparator.reverseOrder()).toList()) {
                    Files.deleteIfExists(f);
                }
            }
        }
    }
}
