package org.kheperasim.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.kheperasim.testing.KheperaAssertions.millis;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A live run's contacts are the engine's events: at the tick the trace first shows them, however often
 * the run is sampled, while a recorded trace's contacts are those its samples saw.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class EngineContactsTest {

    private static Run straightIntoTheWall(long sampleMillis) {
        return Run.of(student.Straight.class).in("lab").seconds(16).seed(3).set("noise.robot", "0")
                .sampleEvery(millis(sampleMillis)).run();
    }

    @Test
    void aLiveContactBeginsAtTheFirstTickTheTraceShowsIt(@TempDir Path dir) {
        Run everyTick = straightIntoTheWall(1);
        Contact exact = everyTick.robot().contacts().get(0);
        // Sampled at every tick, the trace's own contact column sees it first at the very same tick.
        Contact sampled = Run.load(everyTick.saveTo(dir)).robot().contacts().get(0);
        assertEquals(Obstacle.WALL, exact.what());
        assertEquals(sampled.from(), exact.from(), exact + " / " + sampled);
        assertEquals("FRONT", exact.side());
        assertFalse(exact.betweenSamples());
    }

    @Test
    void theContactsTickDoesNotDependOnHowOftenTheRunIsSampled() {
        Contact every50 = straightIntoTheWall(50).robot().contacts().get(0);
        Contact everyTick = straightIntoTheWall(1).robot().contacts().get(0);
        assertEquals(everyTick.from(), every50.from());
        assertEquals(everyTick.to(), every50.to());
    }

    @Test
    void aRecordingOnlyHasTheContactsItsSamplesSaw(@TempDir Path dir) {
        Run live = straightIntoTheWall(50);
        List<Contact> recorded = Run.load(live.saveTo(dir)).robot().contacts();
        assertEquals(1, recorded.size(), recorded.toString());
        assertEquals(0, recorded.get(0).from().nanos() % 50_000_000L, "at a sample: " + recorded);
    }
}
