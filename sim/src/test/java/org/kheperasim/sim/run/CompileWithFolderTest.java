package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The compile path of the window ({@link ControllerCompiler#compile}): a controller compiles with
 * the other {@code .java} files of its folder, as {@code grade} compiles a hand-in, and the paper's
 * Appendix {@code Robot.java}, exactly as printed (no import), compiles, with a warning that names the
 * one import line it lacks.
 */
class CompileWithFolderTest {
    @TempDir
    Path dir;

    @Test
    void aControllerCompilesWithTheHelperClassesOfItsFolder() throws IOException {
        Path src = Files.createDirectories(dir.resolve("hand-in"));
        Files.writeString(src.resolve("Steering.java"), """
                final class Steering {
                    static int[] away(int left, int right) { return left > right ? new int[] {3, -3} : new int[] {5, 5}; }
                }
                """);
        Path hugger = src.resolve("Hugger.java");
        Files.writeString(hugger, """
                import org.kheperasim.api.*;

                public class Hugger extends Controller {
                    @Override
                    protected void doWork() {
                        int[] s = Steering.away(proximity(IrSensor.FRONT_LEFT), proximity(IrSensor.FRONT_RIGHT));
                        setSpeeds(s[0], s[1]);
                        sleepMillis(100);
                    }
                }
                """);
        Files.writeString(src.resolve("Broken.java"), "class Broken { int x = ; }\n");
        ControllerCompiler.Result r = ControllerCompiler.compile(hugger, dir.resolve("classes"));
        assertTrue(r.success(), r.report("Hugger.java"));
        assertTrue(Files.isRegularFile(dir.resolve("classes/Steering.class")), "its helper is compiled too");
        RunResult run = Simulation.builder().arena("lab").classpath(List.of(r.classes())).controller("Hugger").seed(1)
                .seconds(2).console(l -> { }).run();
        assertFalse(run.first().status().failed(), String.valueOf(run.first()));
    }

    @Test
    void theAppendixRobotCompilesAsPrintedAndTheWarningNamesTheImport() throws IOException {
        String appendix;
        try (InputStream in = getClass().getResourceAsStream("/appendix/Robot.java.txt")) {
            appendix = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        Path robot = Files.createDirectories(dir.resolve("appendix")).resolve("Robot.java");
        Files.writeString(robot, appendix);
        ControllerCompiler.Result r = ControllerCompiler.compile(robot, dir.resolve("classes"));
        assertTrue(r.success(), r.report("Robot.java"));
        String report = r.report("Robot.java");
        assertTrue(report.contains("warning") && report.contains("`import org.kheperasim.api.*;`")
                && report.contains("CurrentRobotState"), report);
        RunResult run = Simulation.builder().arena("maze").classpath(List.of(r.classes())).controller("Robot").seed(1)
                .seconds(5).console(l -> { }).run();
        assertFalse(run.first().status().failed(), String.valueOf(run.first()));
        assertTrue(run.first().distanceMm() > 10, "it drives: " + run.first());
    }

    @Test
    void anErrorOfAClassOfTheApiNotImportedNamesTheLineToAdd() throws IOException {
        Path src = Files.createDirectories(dir.resolve("wsu")).resolve("Avoid.java");
        Files.writeString(src, """
                public class Avoid extends RobotController {
                    public void doWork() { setMotorSpeeds(1, 1); }
                    public void close() { }
                }
                """);
        ControllerCompiler.Result r = ControllerCompiler.compile(src, dir.resolve("classes"));
        assertFalse(r.success());
        String report = r.report("Avoid.java");
        assertTrue(report.contains("add the line `import edu.wsu.KheperaSimulator.*;` at the top of the file"), report);
        assertTrue(r.problems().get(0).message().contains("RobotController is a class of the simulator's API"), report);
    }
}
