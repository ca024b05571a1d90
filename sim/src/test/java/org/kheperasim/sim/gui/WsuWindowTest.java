package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.cap;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.horizontal;
import static org.kheperasim.sim.arena.wsu.WsuWorldWriter.Vertex.vertical;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.tools.ToolProvider;
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
        WindowDriverRun.requireXvfb("the WSU window test");
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

        WindowDriverRun.run("the WSU window test", WsuWindowDriver.class, null, 150, new String[] {"WSU WINDOW OK"},
                world.toString(), folder.toString());
        assertTrue(Files.size(WindowDriverRun.target().resolve("wsu-1-running-with-debug-window.png")) > 10_000,
                "a screenshot was saved");
    }
}
