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
 * The run keys work wherever the focus is: a real keyboard (java.awt.Robot under Xvfb, in a child
 * JVM, {@link KeyBindingsDriver}) presses F5, F6, F7, F8, F10 and Space with the focus in the arena
 * view and in the console; then, with an unsaved edit, Ctrl+Q asks first (Cancel keeps the window,
 * Discard closes it). Skipped without Xvfb, except in CI.
 */
class KeyBindingsTest {
    @TempDir
    Path dir;

    @Test
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void f5F6F7F8F10AndSpaceWorkWhereverTheFocusIs() throws Exception {
        Path xvfb = GuiEndToEndTest.xvfb();
        if (xvfb == null) {
            if ("true".equals(System.getenv("CI"))) {
                fail("Xvfb is not installed, and CI=true requires the window tests to run: apt-get install xvfb xauth");
            }
            Assumptions.assumeTrue(false, "Xvfb is not installed; the key bindings test needs it");
        }
        int[] display = new int[1];
        Process x = GuiEndToEndTest.startXvfb(xvfb, display);
        Path target = Path.of("target").toAbsolutePath();
        Files.createDirectories(target);
        Path log = target.resolve("key-bindings-driver.log");
        try {
            Process child = GuiEndToEndTest.childJvm(display[0], KeyBindingsDriver.class.getName(), log, target.toString());
            boolean done = child.waitFor(150, TimeUnit.SECONDS);
            if (!done) {
                child.destroyForcibly();
            }
            String out = Files.readString(log, StandardCharsets.UTF_8);
            assertTrue(done, "the driver did not finish in 150 s:\n" + out);
            assertEquals(0, child.exitValue(), out);
            assertTrue(out.contains("KEYS OK"), out);
            assertTrue(out.contains("SAVE PROMPT OK"), out);
            System.out.println(out);
        } finally {
            x.destroy();
            x.waitFor(5, TimeUnit.SECONDS);
        }
    }
}
