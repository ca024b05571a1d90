package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The window shows the image of the selected robot's vision turret in a strip under the sensor
 * panel once its controller reads the turret, and no strip for a controller that does not. Under
 * Xvfb, in a child JVM ({@link VisionWindowDriver}); screenshots under {@code target/}.
 */
class VisionWindowTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theWindowShowsTheTurretsImageUnderTheSensorPanel() throws Exception {
        WindowDriverRun.requireXvfb("the vision window test");
        Path folder = Files.createDirectories(dir.resolve("controllers"));
        Path source = folder.resolve("LampSeeker.java");
        try (InputStream in = getClass().getResourceAsStream("/vision-window/LampSeeker.java")) {
            Files.write(source, in.readAllBytes());
        }
        assertEquals(0, ToolProvider.getSystemJavaCompiler().run(null, null, null, "-cp",
                System.getProperty("java.class.path"), "-d", folder.toString(), "--release", "17", "-proc:none",
                source.toString()), "the controller compiles");
        WindowDriverRun.run("the vision window test", VisionWindowDriver.class, null, 150,
                new String[] {"VISION WINDOW OK"}, folder.toString());
        assertTrue(Files.size(WindowDriverRun.target().resolve("vision-1-strip.png")) > 10_000, "a screenshot was saved");
    }
}
