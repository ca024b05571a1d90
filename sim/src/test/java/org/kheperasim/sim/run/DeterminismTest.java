package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.io.StringWriter;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.host.HostOptions;

/**
 * Same arena, controller, seed and settings give a byte-identical trace, whatever the threads do;
 * another seed gives another trace; without noise the seed no longer matters.
 */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class DeterminismTest {
    private static final double SECONDS = 120;

    private static String trace(String controller, long seed, Settings settings, HostOptions options) {
        StringWriter out = new StringWriter();
        Simulation.builder().arena("maze").controller(controller).seed(seed).seconds(SECONDS).settings(settings)
                .hostOptions(options).trace(out).sampleMillis(10).run();
        return out.toString();
    }

    private static String trace(String controller, long seed) {
        return trace(controller, seed, Settings.defaults(), HostOptions.defaults());
    }

    private static String body(String trace) {
        return trace.lines().filter(l -> !l.startsWith("#")).collect(Collectors.joining("\n"));
    }

    @Test
    void theSameSeedTwiceGivesTheSameTrace() {
        String a = trace("WallFollower", 11);
        String b = trace("WallFollower", 11);
        assertEquals(a, b);
        assertEquals(SECONDS * 100 + 1, body(a).lines().count(), "one line per 10 ms sample, both ends included");
    }

    @Test
    void randomDelaysInTheControllerThreadChangeNothing() {
        String calm = trace("WallFollower", 12);
        String jittery = trace("WallFollower", 12, Settings.defaults(), HostOptions.defaults().withJitter(300));
        assertEquals(calm, jittery);
        String braitenberg = trace("Braitenberg", 12);
        assertEquals(braitenberg, trace("Braitenberg", 12, Settings.defaults(), HostOptions.defaults().withJitter(300)));
    }

    @Test
    void anotherSeedGivesAnotherTrace() {
        assertNotEquals(body(trace("WallFollower", 13)), body(trace("WallFollower", 14)));
    }

    @Test
    void withoutNoiseTheSeedDoesNotMatter() {
        Settings quiet = Settings.defaults().withNoise(0);
        String a = trace("WallFollower", 15, quiet, HostOptions.defaults());
        String b = trace("WallFollower", 16, quiet, HostOptions.defaults());
        assertNotEquals(a, b, "the headers name different seeds");
        assertEquals(body(a), body(b));
    }
}
