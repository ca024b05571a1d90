package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.api.spi.ControllerException;

/**
 * A helper class compiled for a newer Java than the simulator reads (a fork of the WSU simulator
 * shipped Java 18 class files) refuses its controller before the run in one line, trusted or not:
 * untrusted, the allowlist check reads every class the controller reaches; trusted, the loader reads
 * them as well, so the helper is not first met in the middle of the run as an exception trace.
 */
class TooNewHelperClassTest {
    @TempDir
    Path dir;

    private Path compileWithATooNewHelper() throws IOException {
        Path src = Files.writeString(Files.createDirectories(dir.resolve("src")).resolve("Lazy.java"), """
                import edu.wsu.KheperaSimulator.RobotController;

                public class Lazy extends RobotController {
                    public Lazy() { }
                    public void doWork() throws Exception { setMotorSpeeds(new LazyHelper().speed(), 3); sleep(100); }
                    public void close() throws Exception { }
                }

                class LazyHelper { int speed() { return 3; } }
                """);
        Path out = dir.resolve("classes");
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp",
                System.getProperty("surefire.test.class.path", System.getProperty("java.class.path")), "-d", out.toString(),
                src.toString()));
        Path helper = out.resolve("LazyHelper.class");
        byte[] b = Files.readAllBytes(helper);
        int major = 44 + Runtime.version().feature() + 1;
        b[6] = (byte) (major >> 8);
        b[7] = (byte) major;
        Files.write(helper, b);
        return out;
    }

    @Test
    void aTrustedControllersTooNewHelperIsRefusedBeforeTheRunInOneLine() throws IOException {
        Path classes = compileWithATooNewHelper();
        ControllerException e = assertThrows(ControllerException.class, () -> new ControllerCatalog(List.of(classes), true).load("Lazy"));
        assertTrue(e.getMessage().contains("LazyHelper.class: compiled for Java " + (Runtime.version().feature() + 1)), e.getMessage());
        assertTrue(e.getMessage().endsWith("compile it with `--release 17`") && !e.getMessage().contains("\n"), e.getMessage());
    }

    @Test
    void soIsAnUntrustedOnes() throws IOException {
        Path classes = compileWithATooNewHelper();
        ControllerException e = assertThrows(ControllerException.class, () -> new ControllerCatalog(List.of(classes), false).load("Lazy"));
        assertTrue(e.getMessage().contains("LazyHelper.class: compiled for Java"), e.getMessage());
    }
}
