package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.sim.host.ControllerHost;
import org.kheperasim.sim.host.ControllerStatus;

/** The task of issue 3: CapGatherer brings the caps of two-rooms across to the target region. */
class CapGathererTest {
    /** The stated budget: 20 simulated minutes. */
    private static final double SECONDS = 1200;

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    @Timeout(value = 120, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void deliversAtLeastFourOfTheFiveCapsWithinTwentyMinutes(long seed) {
        RunResult result = Simulation.builder().arena("two-rooms").controller("CapGatherer").seed(seed)
                .seconds(SECONDS).run();
        assertEquals(5, result.caps());
        int delivered = result.capsInRegions().get("target");
        assertTrue(delivered >= 4, "seed " + seed + ": " + delivered + " caps in the target region, "
                + result.capsInRegions());
        assertEquals(ControllerStatus.STOPPED, result.first().status(), "it ran to the end without failing");
    }

    @Test
    @Timeout(value = 120, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void pushingGrabbingAndDroppingCapsIsDeterministicUnderJitter() {
        String calm = trace(ControllerHost.Options.defaults());
        String jittery = trace(ControllerHost.Options.defaults().withJitter(300));
        assertTrue(calm.contains(" cap 0 ") && calm.lines().anyMatch(l -> l.contains(" cap ") && l.endsWith(" 0")),
                "the run moves and holds caps");
        assertEquals(calm, jittery, "real-time jitter at the controller hand-offs changes nothing");
    }

    private static String trace(ControllerHost.Options options) {
        StringWriter out = new StringWriter();
        Simulation.builder().arena("two-rooms").controller("CapGatherer").seed(3).seconds(120)
                .hostOptions(options).trace(out).sampleMillis(10).run();
        return out.toString();
    }
}
