package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Replay in the window: a one-hour recording opens; the timeline, dragged with the mouse, scrubs
 * to the middle; Play plays, a faster speed races, Rewind goes back; each time the robot drawn is
 * where the trace has it; an unsaved edit made before comes back with Close replay, still marked
 * unsaved, so Ctrl+Q asks. Under Xvfb, in a child JVM ({@link ReplayWindowDriver}); screenshots and
 * the exported plot under {@code target/}. Skipped without Xvfb, except in CI.
 */
class ReplayWindowTest {
    @Test
    @Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aRecordingIsScrubbedPlayedAndRewoundAsTheTraceSays() throws Exception {
        WindowDriverRun.run("the replay window test", ReplayWindowDriver.class, null, 210,
                new String[] {"REPLAY OK", "UNSAVED EDITS KEPT OK"});
        Path target = WindowDriverRun.target();
        assertTrue(Files.size(target.resolve("replay-1-middle.png")) > 10_000, "a screenshot was saved");
        // 0 to 3600 s every 50 ms, and the header.
        try (var lines = Files.lines(target.resolve("replay-plot.csv"))) {
            assertEquals(72_002, lines.count(), "the whole run's samples");
        }
    }
}
