package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * On a 1366 × 768 laptop screen the window opens within the screen, console included (it used to
 * open at a fixed 1180 × 900). Under Xvfb, in a child JVM ({@link WindowFitDriver}); skipped without
 * Xvfb, except in CI.
 */
class WindowFitTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theWindowFitsALaptopScreenWithItsConsole() throws Exception {
        Path xvfb = GuiEndToEndTest.xvfb();
        if (xvfb == null) {
            if ("true".equals(System.getenv("CI"))) {
                fail("Xvfb is not installed, and CI=true requires the window tests to run: apt-get install xvfb xauth");
            }
            Assumptions.assumeTrue(false, "Xvfb is not installed; the window size test needs it");
        }
        int[] display = new int[1];
        Process x = GuiEndToEndTest.startXvfb(xvfb, display, "1366x768x24");
        Path target = Path.of("target").toAbsolutePath();
        Files.createDirectories(target);
        Path log = target.resolve("window-fit-driver.log");
        try {
            Process child = GuiEndToEndTest.childJvm(display[0], WindowFitDriver.class.getName(), log, target.toString());
            boolean done = child.waitFor(150, TimeUnit.SECONDS);
            if (!done) {
                child.destroyForcibly();
            }
            String out = Files.readString(log, StandardCharsets.UTF_8);
            assertTrue(done, "the driver did not finish in 150 s:\n" + out);
            assertEquals(0, child.exitValue(), out);
            assertTrue(out.contains("FIT OK"), out);
            System.out.println(out);
        } finally {
            x.destroy();
            x.waitFor(5, TimeUnit.SECONDS);
        }
    }
}
