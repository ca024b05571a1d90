package org.kheperasim.sim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.testfixtures.Cli;

/**
 * {@code run --controller Hugger.java} compiles the source with the other {@code .java} files of its
 * folder, as the window and {@code grade} do, and runs it; a source that does not compile ends the
 * command with one line naming its first error, exit status 2.
 */
class RunJavaSourceTest {
    @TempDir
    Path dir;

    @Test
    void runCompilesTheSourceWithItsFolderAndRunsIt() throws IOException {
        Files.writeString(dir.resolve("Steering.java"), """
                final class Steering {
                    static int speed() { return 4; }
                }
                """);
        Path hugger = Files.writeString(dir.resolve("Hugger.java"), """
                import org.kheperasim.api.*;

                public class Hugger extends Controller {
                    @Override
                    protected void doWork() {
                        setSpeeds(Steering.speed(), Steering.speed());
                        sleepMillis(100);
                    }
                }
                """);
        Cli.Printed p = Cli.main("run", "--arena", "lab", "--controller", hugger.toString(), "--seconds", "2", "--seed", "1");
        assertEquals(0, p.code(), p.out() + p.err());
        assertTrue(p.out().contains("Hugger in lab: 2.0 s simulated"), p.out());
    }

    @Test
    void aSourceThatDoesNotCompileIsOneLineAndExitStatusTwo() throws IOException {
        Path bad = Files.writeString(dir.resolve("Bad.java"), """
                public class Bad extends org.kheperasim.api.Controller {
                    protected void doWork() { setSpeeds(1, 1) }
                }
                """);
        Cli.Printed p = Cli.main("run", "--arena", "lab", "--controller", bad.toString(), "--seconds", "2");
        assertEquals(2, p.code(), p.out() + p.err());
        assertTrue(p.err().contains("khepera-sim: error: Bad.java does not compile: Bad.java:2:"), p.err());
    }
}
