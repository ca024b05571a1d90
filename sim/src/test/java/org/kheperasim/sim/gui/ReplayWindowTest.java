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

/**
 * Replay in the window: a one-hour recording opens; the timeline, dragged with the mouse, scrubs
 * to the middle; Play plays, a faster speed races, Rewind goes back; each time the robot drawn is
 * where the trace has it. Under Xvfb, in a child JVM ({@link ReplayWindowDriver}); screenshots and
 * the exported plot under {@code target/}. Skipped without Xvfb, except in CI.
 */
class ReplayWindowTest {
    @Test
    @Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aRecordingIsScrubbedPlayedAndRewoundAsTheTraceSays() throws Exception {
        Path xvfb = GuiEndToEndTest.xvfb();
        if (xvfb == null) {
            if ("true".equals(System.getenv("CI"))) {
                fail("Xvfb is not installed, and CI=true requires the window tests to run: apt-get install xvfb xauth");
            }
            Assumptions.assumeTrue(false, "Xvfb is not installed; the replay window test needs it");
        }
        int[] display = new int[1];
        Process x = GuiEndToEndTest.startXvfb(xvfb, display);
        Path target = Path.of("target").toAbsolutePath();
        Files.createDirectories(target);
        Path log = target.resolve("replay-window-driver.log");
        try {
            Process child = GuiEndToEndTest.childJvm(display[0], ReplayWindowDriver.class.getName(), log, target.toString());
            boolean done = child.waitFor(210, TimeUnit.SECONDS);
            if (!done) {
                child.destroyForcibly();
            }
            String out = Files.readString(log, StandardCharsets.UTF_8);
            assertTrue(done, "the driver did not finish in 210 s:\n" + out);
            assertEquals(0, child.exitValue(), out);
            assertTrue(out.contains("REPLAY OK"), out);
            assertTrue(Files.size(target.resolve("replay-1-middle.png")) > 10_000, "a screenshot was saved");
            // 0 to 3600 s every 50 ms, and the header.
            assertEquals(72_002, Files.lines(target.resolve("replay-plot.csv")).count(), "the whole run's samples");
            System.out.println(out);
        } finally {
            x.destroy();
            x.waitFor(5, TimeUnit.SECONDS);
        }
    }
}
