package org.kheperasim.sim.host.loading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.run.WsuCorpusEntryPointsTest;

/**
 * The public WSU course code passes the allowlist, but for controllers that open a window of their
 * own, which are refused with the advice to run them trusted, and henrihs/stupid-robot's
 * {@code Executors} pool, whose refusal names the replacement (docs/controller-rules.md). The sets
 * are {@link WsuCorpusEntryPointsTest}'s source folders, each compiled as a whole against the
 * simulator's classes (plus {@code -Dkheperasim.wsuCorpus.classpath} when course code needs API
 * methods this build lacks), the original simulator's own sources ({@code edu/wsu/KheperaSimulator})
 * left unread. The corpus is not part of the repository: give its folder with
 * {@code -Dkheperasim.wsuCorpus=DIR} (default {@code ../shared/wsu-corpus} beside the repository;
 * the test is skipped when there is none). The counts are printed.
 */
class WsuCorpusAllowlistTest {
    @TempDir
    Path dir;

    @Test
    void theCourseControllersPassButThoseThatOpenAWindow() throws IOException {
        Path corpus = Path.of(System.getProperty("kheperasim.wsuCorpus",
                Path.of(System.getProperty("kheperasim.repoRoot", "..")).resolve("../shared/wsu-corpus").toString()));
        Assumptions.assumeTrue(Files.isDirectory(corpus), "no WSU course corpus at " + corpus.toAbsolutePath()
                + " (give one with -Dkheperasim.wsuCorpus=DIR)");
        List<Path> folders = new ArrayList<>();
        for (String set : WsuCorpusEntryPointsTest.SETS.values()) {
            Path root = corpus.resolve(set);
            if (!set.endsWith("controllers") && Files.isDirectory(root)) {
                folders.add(root);
            }
        }
        Assumptions.assumeFalse(folders.isEmpty(), "no course sets under " + corpus.toAbsolutePath());
        int files = 0;
        List<String> classes = new ArrayList<>();
        List<String> refused = new ArrayList<>();
        Map<String, String> notCompiled = new TreeMap<>();
        for (Path folder : folders) {
            List<Path> sources = sources(folder);
            files += sources.size();
            Path out = Files.createDirectories(dir.resolve("f" + folders.indexOf(folder)));
            String failure = compile(sources, out);
            if (failure != null) {
                notCompiled.put(corpus.relativize(folder).toString(), failure);
                continue;
            }
            for (String r : AllowlistOnRealCodeTest.refusals(out, classes)) {
                refused.add(corpus.relativize(folder) + "/" + r);
            }
        }
        System.out.printf("WSU corpus %s: %d source files in %d folders, %d classes checked, %d refused%n", corpus, files,
                folders.size(), classes.size(), refused.size());
        refused.forEach(r -> System.out.println("  refused: " + r));
        notCompiled.forEach((f, why) -> System.out.println("  not compiled (needs API this build lacks?): " + f + ": " + why));
        assertTrue(files > 0, "the corpus holds course sources: " + corpus);
        assertEquals(Map.of(), notCompiled, "every course folder compiles against the simulator (add API stubs with"
                + " -Dkheperasim.wsuCorpus.classpath)");
        assertEquals(List.of(), refused.stream().filter(r -> !r.contains("a controller that opens a window of its own runs"
                + " only trusted") && !r.contains("thread pools run tasks on threads the JDK starts itself")).toList(),
                "only controllers that open a window, or use a thread pool (the refusal names the replacement), are refused");
    }

    private static boolean isOriginalSimulator(Path d) {
        return d.toString().replace('\\', '/').contains("edu/wsu/KheperaSimulator");
    }

    /** The course's sources under a set's root, without the original simulator's own. */
    private static List<Path> sources(Path root) throws IOException {
        try (Stream<Path> all = Files.walk(root)) {
            return all.filter(p -> p.toString().endsWith(".java")).filter(p -> !isOriginalSimulator(root.relativize(p)))
                    .sorted().toList();
        }
    }

    /** @return null when the sources compiled, else the compiler's first lines */
    private static String compile(List<Path> sources, Path out) {
        String extra = System.getProperty("kheperasim.wsuCorpus.classpath", "");
        String classpath = (extra.isEmpty() ? "" : extra + File.pathSeparator) + System.getProperty("java.class.path");
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        StringWriter messages = new StringWriter();
        boolean ok = javac.getTask(messages, null, null, List.of("-cp", classpath, "-d", out.toString(), "--release", "17",
                "-proc:none", "-nowarn", "-encoding", "ISO-8859-1"), null, javac.getStandardFileManager(null, null,
                        StandardCharsets.ISO_8859_1).getJavaFileObjectsFromPaths(sources)).call();
        return ok ? null : messages.toString().lines().limit(3).reduce("", (a, b) -> a + b + " ");
    }
}
