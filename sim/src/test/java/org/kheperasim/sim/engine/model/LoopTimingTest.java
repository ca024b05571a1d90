package org.kheperasim.sim.engine.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.run.Simulation;

/**
 * {@code wsu.loopTiming}: by default a WSU controller's loop pauses exactly the 20 ms it asks; under
 * {@code desktop} (the wsu profile) each pause is lengthened as the original's were on a desktop Java,
 * drawn from the run's seed: the same seed gives the same pauses, another seed others.
 */
class LoopTimingTest {
    /** The loop's periods, µs, of a {@code WsuLoopClock} run for 10 simulated s. */
    private static long[] periods(Settings settings, long seed) {
        List<ConsoleLine> console = new CopyOnWriteArrayList<>();
        Simulation.builder().arena("lab").controller("org.kheperasim.testcontrollers.WsuLoopClock").seed(seed)
                .seconds(10).settings(settings).console(console::add).run();
        String line = console.stream().map(ConsoleLine::text).filter(t -> t.contains("periods ")).findFirst()
                .orElseThrow(() -> new AssertionError("no periods line: " + console));
        return Arrays.stream(line.substring(line.indexOf("periods ") + 8).trim().split(" ")).mapToLong(Long::parseLong)
                .toArray();
    }

    @Test
    void theDistributionIsTheMeasuredOne() {
        assertEquals(40_000, LoopTiming.extraNanos(0));
        assertEquals(100_000, LoopTiming.extraNanos(0.5), "20.10 ms at the median");
        assertEquals(1_050_000, LoopTiming.extraNanos(0.9));
        assertEquals(31_380_000, LoopTiming.extraNanos(0.99));
        assertEquals(204_150_000, LoopTiming.extraNanos(1));
        long last = -1;
        for (int i = 0; i <= 1000; i++) {
            long e = LoopTiming.extraNanos(i / 1000.0);
            assertTrue(e >= last, "grows with the draw");
            last = e;
        }
    }

    @Test
    void byDefaultEveryPauseIsTheSame() {
        long[] p = periods(Settings.defaults(), 1);
        assertEquals(300, p.length);
        assertEquals(1, Arrays.stream(p).distinct().count(), "one period: " + Arrays.toString(p));
        assertTrue(p[0] >= 20_000, "at least the 20 ms asked: " + p[0]);
    }

    @Test
    void onTheDesktopPausesVaryAsTheOriginalsDidAndFollowTheSeed() {
        Settings desktop = Settings.defaults().with(LoopTiming.KEY, LoopTiming.DESKTOP);
        long base = periods(Settings.defaults(), 1)[0];
        long[] p = periods(desktop, 1);
        assertEquals(300, p.length);
        List<Long> extra = new ArrayList<>();
        for (long v : p) {
            assertTrue(v >= base, "never shorter than asked: " + v + " µs");
            extra.add(v - base);
        }
        long longer = extra.stream().filter(e -> e >= 1_000).count();
        long far = extra.stream().filter(e -> e >= 10_000).count();
        // The measured distribution: 10 % of pauses at least 1 ms longer, about 1.5 % at least 10 ms.
        assertTrue(longer >= 10 && longer <= 60, longer + " of 300 pauses at least 1 ms longer: " + extra);
        assertTrue(far >= 1 && far <= 15, far + " of 300 pauses at least 10 ms longer: " + extra);
        assertEquals(Arrays.toString(p), Arrays.toString(periods(desktop, 1)), "the same seed, the same pauses");
        assertNotEquals(Arrays.toString(p), Arrays.toString(periods(desktop, 2)), "another seed, other pauses");
        assertTrue(WsuProfile.settings().containsKey(LoopTiming.KEY), "the wsu profile sets it");
    }
}
