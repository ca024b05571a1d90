package org.kheperasim.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.sandbox.BoxProbe;

/**
 * The runnable jar ({@code target/khepera-sim.jar}, so this runs after {@code package}) named as a user
 * names it: by a relative path (the README's {@code java -jar sim/target/khepera-sim.jar} from the
 * checkout), through a symbolic link, and as a copy in the current folder (docs/grading.md's
 * {@code java -jar khepera-sim.jar}): {@code grade} makes every run, ok, in the sandbox and without it,
 * and {@code run --sandbox} runs with a relative {@code --classpath}. Each of these gave every student
 * {@code error} (ClassNotFoundException) until the runs were started from the jar's real location.
 */
@Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class GradeAnyJarIT {
    private static final Path JAR = Path.of("target", "khepera-sim.jar").toAbsolutePath();

    @TempDir
    Path dir;

    @Test
    void gradeFromARelativeALinkedAndACopiedJar() throws Exception {
        assertTrue(Files.isRegularFile(JAR), "the runnable jar is built before the integration tests: " + JAR);
        Path subs = dir.resolve("subs");
        Files.createDirectories(subs.resolve("alice"));
        Files.copy(Path.of("src", "test", "resources", "grade", "alice", "Explorer.java"),
                subs.resolve("alice").resolve("Explorer.java"));
        Path cwd = Files.createDirectories(dir.resolve("cwd"));
        Files.createSymbolicLink(cwd.resolve("link.jar"), JAR);
        Files.copy(JAR, cwd.resolve("khepera-sim.jar"));
        String relative = cwd.toAbsolutePath().relativize(JAR).toString();
        boolean box = BoxProbe.unavailable().isEmpty();
        List<String> sandbox = box ? List.of() : List.of("--no-sandbox");
        grade(cwd, relative, sandbox, "relative");
        grade(cwd, "link.jar", List.of("--no-sandbox"), "link");
        grade(cwd, "khepera-sim.jar", sandbox, "copy");
    }

    @Test
    void runInTheSandboxFromALinkedJarWithARelativeClasspath() throws Exception {
        Hostile.requireBox();
        assertTrue(Files.isRegularFile(JAR), "the runnable jar is built before the integration tests: " + JAR);
        Path cwd = Files.createDirectories(dir.resolve("cwd"));
        Files.createSymbolicLink(cwd.resolve("link.jar"), JAR);
        Path src = Files.createDirectories(dir.resolve("src"));
        Files.copy(Path.of("src", "test", "resources", "grade", "alice", "Explorer.java"), src.resolve("Explorer.java"));
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp", JAR.toString(), "-d",
                cwd.resolve("out").toString(), src.resolve("Explorer.java").toString()));
        String printed = java(cwd, List.of("-jar", "link.jar", "run", "--sandbox", "--arena", "lab", "--classpath", "out",
                "--controller", "Explorer", "--seconds", "2", "--seed", "1", "--trace", "run.trace"), 0);
        assertTrue(printed.contains("Explorer in lab: 2.0 s simulated"), printed);
        assertTrue(Files.size(cwd.resolve("run.trace")) > 0, "the trace is written where the relative path names it");
    }

    private void grade(Path cwd, String jar, List<String> sandbox, String way) throws IOException, InterruptedException {
        Path out = dir.resolve("out-" + way);
        List<String> args = new ArrayList<>(List.of("-jar", jar, "grade", "--submissions", dir.resolve("subs").toString(),
                "--arenas", "lab", "--seeds", "1", "--seconds", "2", "--wall-limit", "60", "--heap-mb", "128", "--out",
                out.toString()));
        args.addAll(sandbox);
        String printed = java(cwd, args, 0);
        RunRecord alice = ReportFiles.readCsv(out.resolve("results.csv")).get(0);
        assertEquals(RunStatus.OK, alice.status(), way + " " + sandbox + ": " + alice + "\n" + printed);
    }

    private String java(Path cwd, List<String> args, int expected) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(args);
        Path printed = dir.resolve("printed.txt");
        Process p = new ProcessBuilder(cmd).directory(cwd.toFile()).redirectErrorStream(true)
                .redirectOutput(printed.toFile()).start();
        assertTrue(p.waitFor(150, TimeUnit.SECONDS), "ended in time");
        String text = Files.readString(printed, StandardCharsets.UTF_8);
        assertEquals(expected, p.exitValue(), text);
        return text;
    }
}
