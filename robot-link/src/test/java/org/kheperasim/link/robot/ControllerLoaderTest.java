package org.kheperasim.link.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.api.spi.ControllerException;

class ControllerLoaderTest {
    @TempDir
    Path dir;

    @Test
    void bundledNamesAreTheSimulators() {
        assertEquals(List.of("WallFollower", "Braitenberg", "Template", "CapGatherer", "MazeExplorer", "LightFollower", "StepBraitenberg", "Aggregation"),
                ControllerLoader.bundled());
        assertEquals("org.kheperasim.controllers.Braitenberg", new ControllerLoader(List.of()).load("Braitenberg").getName());
    }

    @Test
    void aStudentsClassLoadsFromTheClasspathUnchanged() throws Exception {
        Path src = dir.resolve("Robot.java");
        Files.writeString(src, "import org.kheperasim.api.*;\n"
                + "public class Robot extends Thread {\n"
                + "  public Robot(CurrentRobotState s, MessagePasser m) {}\n"
                + "  public void run() { try { Thread.sleep(1); } catch (InterruptedException e) {} }\n"
                + "}\n");
        Path out = Files.createDirectories(dir.resolve("out"));
        int rc = ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp",
                System.getProperty("surefire.test.class.path", System.getProperty("java.class.path")),
                "-d", out.toString(), src.toString());
        assertEquals(0, rc);
        Class<?> robot = new ControllerLoader(List.of(out)).load("Robot");
        assertEquals("Robot", robot.getName());
        assertNotSame(ControllerLoader.class.getClassLoader(), robot.getClassLoader());
    }

    @Test
    void anUnknownNameSaysWhereItLooked() {
        ControllerException e = assertThrows(ControllerException.class, () -> new ControllerLoader(List.of()).load("Nope"));
        assertTrue(e.getMessage().contains("no controller named 'Nope'") && e.getMessage().contains("WallFollower")
                && e.getMessage().contains("khepera-link.jar"), e.getMessage());
        ControllerException missing = assertThrows(ControllerException.class,
                () -> new ControllerLoader(List.of(dir.resolve("absent"))));
        assertTrue(missing.getMessage().contains("absent"), missing.getMessage());
    }
}
