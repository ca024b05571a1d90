package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ControllerStatus;

/** A student's .java compiles in the window's compile service; errors name their lines; the class runs. */
class ControllerCompilerTest {

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aGoodControllerCompilesLoadsAndRuns(@TempDir Path dir) throws Exception {
        Path src = dir.resolve("Spinner.java");
        Files.writeString(src, """
                import org.kheperasim.api.*;

                public class Spinner extends Controller {
                    @Override
                    protected void doWork() {
                        setSpeeds(2, -2);
                        sleepMillis(100);
                    }
                }
                """);
        ControllerCompiler.Result r = ControllerCompiler.compile(src, dir.resolve("classes"));
        assertTrue(r.success(), r.report("Spinner.java"));
        assertEquals("Spinner", r.className());
        RunResult run = Simulation.builder().arena("lab").controller(r.className()).classpath(List.of(r.classes()))
                .seed(1).seconds(5).run();
        assertTrue(StrictMath.abs(run.first().headingDeg() - 90) > 10, "the compiled controller turned the robot: " + run.first());
    }

    @Test
    void errorsComeWithTheirLineNumbers(@TempDir Path dir) throws Exception {
        Path src = dir.resolve("Broken.java");
        Files.writeString(src, """
                import org.kheperasim.api.*;

                public class Broken extends Controller {
                    @Override
                    protected void doWork() {
                        setSpeeds(2, -2)
                        int x = "text";
                    }
                }
                """);
        ControllerCompiler.Result r = ControllerCompiler.compile(src, dir.resolve("classes"));
        assertFalse(r.success());
        assertTrue(r.problems().stream().anyMatch(p -> p.error() && p.line() == 6), r.report("Broken.java"));
        assertTrue(r.report("Broken.java").contains("Broken.java:6:"), r.report("Broken.java"));
    }

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void anExceptionPointsAtTheStudentsLineAndStopsTheRobot(@TempDir Path dir) throws Exception {
        Path src = dir.resolve("Thrower.java");
        Files.writeString(src, """
                import org.kheperasim.api.*;

                public class Thrower extends Controller {
                    private int n;

                    @Override
                    protected void doWork() {
                        setSpeeds(3, 3);
                        sleepMillis(100);
                        if (++n == 5) {
                            int[] a = new int[2];
                            a[n] = 1;
                        }
                    }
                }
                """);
        ControllerCompiler.Result r = ControllerCompiler.compile(src, dir.resolve("classes"));
        assertTrue(r.success(), r.report("Thrower.java"));
        StringBuilder console = new StringBuilder();
        RunResult run = Simulation.builder().arena("lab").controller("Thrower").classpath(List.of(r.classes()))
                .seed(1).seconds(3).console(l -> {
                    if (l.kind() == ConsoleLine.Kind.ERROR) {
                        console.append(l.format());
                    }
                }).run();
        assertEquals(ControllerStatus.FAILED, run.first().status());
        assertTrue(console.toString().contains("Thrower.java:12"), console.toString());
    }
}
