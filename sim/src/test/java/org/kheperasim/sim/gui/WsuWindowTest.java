package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.cap;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.horizontal;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.vertical;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.wsu.WsuWorldWriter;

/**
 * The window opens a WSU world file and runs a WSU controller folder whose controller opens its
 * own debug window; stopping the run closes that window. Under Xvfb, in a child JVM
 * ({@link WsuWindowDriver}); screenshots under {@code target/}. Skipped without Xvfb, except in CI.
 */
class WsuWindowTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theWindowRunsAWsuControllerFolderOnAWsuWorldAndClosesItsDebugWindowWithTheRun() throws Exception {
        Path xvfb = GuiEndToEndTest.xvfb();
        if (xvfb == null) {
            if ("true".equals(System.getenv("CI"))) {
                fail("Xvfb is not installed, and CI=true requires the window tests to run: apt-get install xvfb xauth");
            }
            Assumptions.assumeTrue(false, "Xvfb is not installed; the WSU window test needs it");
        }
        Path folder = Files.createDirectories(dir.resolve("controllers"));
        Path source = folder.resolve("WsuDebugWindow.java");
        try (InputStream in = getClass().getResourceAsStream("/wsu-window/WsuDebugWindow.java")) {
            Files.write(source, in.readAllBytes());
        }
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp",
                System.getProperty("java.class.path"), "-d", folder.toString(), "--release", "17", "-proc:none",
                source.toString()), "the WSU controller compiles");
        Path world = dir.resolve("course.map");
        Files.write(world, WsuWorldWriter.world(List.of(cap(1, 330, 100), vertical(2, 400, 150),
                horizontal(3, 100, 400))));

        int[] display = new int[1];
        Process x = GuiEndToEndTest.startXvfb(xvfb, display);
        Path target = Path.of("target").toAbsolutePath();
        Files.createDirectories(target);
        Path log = target.resolve("wsu-window-driver.log");
        try {
            Process child = GuiEndToEndTest.childJvm(display[0], WsuWindowDriver.class.getName(), log, target.toString(),
                    world.toString(), folder.toString());
            boolean done = child.waitFor(150, TimeUnit.SECONDS);
            if (!done) {
                child.destroyForcibly();
            }
            String out = Files.readString(log, StandardCharsets.UTF_8);
            assertTrue(done, "the driver did not finish in 150 s:\n" + out);
            assertEquals(0, child.exitValue(), out);
            assertTrue(out.contains("WSU WINDOW OK"), out);
            assertTrue(Files.size(target.resolve("wsu-1-running-with-debug-window.png")) > 10_000, "a screenshot was saved");
            System.out.println(out);
        } finally {
            x.destroy();
            x.waitFor(5, TimeUnit.SECONDS);
        }
    }
}
