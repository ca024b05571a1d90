package org.kheperasim.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The simulator's jar as a student keeps it: copied into a home folder whose name holds a space and
 * accents ({@code Élève dossier/khepera sim é.jar}), with a CRLF controller beside it compiled by javac
 * against the jar, a CRLF arena, and a trace written to a folder of the same kind; then {@code verify}
 * of that trace. The jar is the one the build packaged (sim is packaged before this module's tests in
 * {@code mvn verify}); a build that stops at {@code test} has none and skips, saying so.
 */
@Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class JarInAStudentsFolderTest {
    private static final String CONTROLLER = "import org.kheperasim.api.*;\n\npublic class Hello extends Controller {\n"
            + "    @Override\n    protected void doWork() {\n        setSpeeds(proximity(IrSensor.FRONT_LEFT) > 500 ? -3 : 4, 4);\n"
            + "        sleepMillis(100);\n    }\n}\n";
    private static final String ARENA = "# a box\nkhepera-arena 1\nname box\nsize 1000 1000\nrobot 500 500 0\n"
            + "wall 0 0 1000 0 8\nwall 0 1000 1000 1000 8\nwall 0 0 0 1000 8\nwall 1000 0 1000 1000 8\n";

    @TempDir
    Path home;

    private static String crlf(String s) {
        return s.replace("\n", "\r\n");
    }

    private static String run(Path folder, String... command) throws Exception {
        List<String> cmd = new ArrayList<>();
        for (String c : command) {
            cmd.add(c.equals("java") || c.equals("javac") ? Path.of(System.getProperty("java.home"), "bin", c).toString() : c);
        }
        Process p = new ProcessBuilder(cmd).directory(folder.toFile()).redirectErrorStream(true).start();
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), String.join(" ", command));
        assertEquals(0, p.exitValue(), String.join(" ", command) + " in " + folder + ":\n" + out);
        return out;
    }

    @Test
    void theJarRunsFromAFolderWithSpacesAndAccents() throws Exception {
        Path built = Path.of(System.getProperty("kheperasim.repoRoot", "..")).resolve("sim/target/khepera-sim.jar");
        Assumptions.assumeTrue(Files.isRegularFile(built),
                "sim/target/khepera-sim.jar is not built (mvn verify packages it before these tests; mvn test does not)");
        Path folder = Files.createDirectories(home.resolve("Élève dossier"));
        Path jar = Files.copy(built, folder.resolve("khepera sim é.jar"), StandardCopyOption.REPLACE_EXISTING);
        Files.writeString(folder.resolve("Hello.java"), crlf(CONTROLLER));
        Files.writeString(folder.resolve("boîte é.arena"), crlf(ARENA));

        run(folder, "javac", "-cp", jar.toString(), "-d", "classes é", "Hello.java");
        String out = run(folder, "java", "-jar", jar.toString(), "run", "--arena", "boîte é.arena", "--classpath", "classes é",
                "--controller", "Hello", "--seconds", "10", "--seed", "1", "--trace", "traces é/run 1.trace");
        assertTrue(out.contains("Hello in box: 10.0 s simulated"), out);
        assertTrue(Files.size(folder.resolve("traces é").resolve("run 1.trace")) > 0);
        String verify = run(folder, "java", "-jar", jar.toString(), "verify", "--arena", "boîte é.arena", "--classpath", "classes é",
                "traces é/run 1.trace");
        assertTrue(verify.startsWith("identical"), verify);
    }
}
