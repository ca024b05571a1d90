package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import org.kheperasim.sim.host.HostOptions;

/**
 * CapGatherer moves, grabs and drops caps deterministically. That it delivers every cap on 20 seeds
 * is in {@link AssignmentScoresTest}.
 */
class CapGathererTest {
    @Test
    @Timeout(value = 120, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void pushingGrabbingAndDroppingCapsIsDeterministicUnderJitter() {
        String calm = trace(HostOptions.defaults());
        String jittery = trace(HostOptions.defaults().withJitter(300));
        assertTrue(calm.contains(" cap 0 ") && calm.lines().anyMatch(l -> l.contains(" cap ") && l.endsWith(" 0")),
                "the run moves and holds caps");
        assertEquals(calm, jittery, "real-time jitter at the controller hand-offs changes nothing");
    }

    private static String trace(HostOptions options) {
        StringWriter out = new StringWriter();
        Simulation.builder().arena("two-rooms").controller("CapGatherer").seed(3).seconds(120)
                .hostOptions(options).trace(out).sampleMillis(10).run();
        return out.toString();
    }
}
