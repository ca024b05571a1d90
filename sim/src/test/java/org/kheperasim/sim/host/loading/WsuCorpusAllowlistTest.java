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

/**
 * The public WSU course code (the {@code Nepetalactone/Systemarchitekturen-FHV} folders ue4 and ue5,
 * and {@code christianLins/KheperaRobotControl}'s RobotControl1/src) passes the allowlist, but for
 * controllers that open a window of their own, which are refused with the advice to run them
 * trusted. The corpus is not part of the repository: give its folder with
 * {@code -Dkheperasim.wsuCorpus=DIR} (default {@code ../shared/wsu-corpus} beside the repository;
 * the test is skipped when there is none). Every folder under it that holds {@code .java} files is
 * compiled on its own against the simulator's classes, plus {@code -Dkheperasim.wsuCorpus.classpath}
 * when the course code needs API methods this build lacks. Sources in an
 * {@code edu/wsu/KheperaSimulator} folder are the original simulator's, not course code: they are
 * left unread. The counts are printed.
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
        List<Path> folders;
        try (Stream<Path> all = Files.walk(corpus)) {
            folders = all.filter(Files::isDirectory).filter(d -> !isOriginalSimulator(d)).filter(WsuCorpusAllowlistTest::hasSources)
                    .sorted().toList();
        }
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
                + " only trusted")).toList(), "only controllers that open a window are refused");
    }

    private static boolean isOriginalSimulator(Path d) {
        return d.toString().replace('\\', '/').contains("edu/wsu/KheperaSimulator");
    }

    private static boolean hasSources(Path d) {
        try {
            return !sources(d).isEmpty();
        } catch (IOException e) {
            return false;
        }
    }

    private static List<Path> sources(Path folder) throws IOException {
        try (Stream<Path> list = Files.list(folder)) {
            return list.filter(p -> p.toString().endsWith(".java")).sorted().toList();
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
