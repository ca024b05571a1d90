package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.sandbox.BoxProbe;

/**
 * {@code grade} started with the simulator's classpath given relative to the current folder, one entry
 * of it a symbolic link (as {@code java -jar khepera-sim.jar} or a linked jar gives it): every run is
 * made, and ok, on warm workers without the sandbox and in a JVM per run in it (without it where there is no
 * bubblewrap). Until the runs were
 * started from the classpath's real location they ran in another folder and found no simulator class:
 * every student {@code error}. (The runnable jar itself, named relatively, through a link and as a copy
 * in the current folder: {@code GradeAnyJarIT}.)
 */
class GradeFromAnyFolderTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aRelativeAndLinkedClasspathGradesOk() throws Exception {
        Path subs = dir.resolve("subs");
        Files.createDirectories(subs.resolve("alice"));
        Files.copy(Path.of("src", "test", "resources", "grade", "alice", "Explorer.java"),
                subs.resolve("alice").resolve("Explorer.java"));
        Path cwd = Files.createDirectories(dir.resolve("cwd"));
        String classpath = relativeWithALink(cwd);
        boolean box = BoxProbe.unavailable().isEmpty();
        // Warm workers without the box; a JVM per run in the box (without bubblewrap: without it).
        List<List<String>> ways = List.of(List.of("--no-sandbox"),
                box ? List.of("--worker-runs", "1") : List.of("--no-sandbox", "--worker-runs", "1"));
        for (List<String> way : ways) {
            Path out = dir.resolve("out" + ways.indexOf(way));
            List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-XX:TieredStopAtLevel=1", "-cp", classpath, "org.kheperasim.sim.cli.Main", "grade", "--submissions", subs.toAbsolutePath().toString(),
                    "--arenas", "lab", "--seeds", "1", "--seconds", "2", "--wall-limit", "60", "--heap-mb", "128", "--out",
                    out.toAbsolutePath().toString()));
            cmd.addAll(way);
            Process p = new ProcessBuilder(cmd).directory(cwd.toFile()).redirectErrorStream(true)
                    .redirectOutput(dir.resolve("printed.txt").toFile()).start();
            p.waitFor(150, TimeUnit.SECONDS);
            String printed = Files.readString(dir.resolve("printed.txt"), StandardCharsets.UTF_8);
            assertEquals(0, p.exitValue(), way + ": " + printed);
            RunRecord alice = ReportFiles.readCsv(out.resolve("results.csv")).get(0);
            assertEquals(RunStatus.OK, alice.status(), way + ": " + alice);
        }
    }

    /** The test's classpath relative to {@code cwd}, with the simulator's classes folder through a link there. */
    private static String relativeWithALink(Path cwd) throws IOException {
        Path own = Path.of(Grader.class.getProtectionDomain().getCodeSource().getLocation().getPath()).toAbsolutePath();
        Path link = Files.createSymbolicLink(cwd.resolve("sim-classes"), own);
        StringBuilder cp = new StringBuilder();
        for (String e : System.getProperty("java.class.path").split(File.pathSeparator)) {
            if (e.isEmpty()) {
                continue;
            }
            Path abs = Path.of(e).toAbsolutePath();
            String rel = abs.equals(own) ? cwd.relativize(link).toString() : cwd.toAbsolutePath().relativize(abs).toString();
            cp.append(cp.length() > 0 ? File.pathSeparator : "").append(rel);
        }
        return cp.toString();
    }
}
