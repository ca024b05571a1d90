package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.kheperasim.sim.engine.event.EngineEvent;

/**
 * The golden traces once more, each run with the engine's events watched: the trace is still the
 * committed one, byte for byte (watching reads the engine and changes nothing of the run).
 */
class GoldenTraceWithEventsTest {
    private static final Path REPO = Path.of(System.getProperty("kheperasim.repoRoot", ".."));
    private static final Path GOLDEN = REPO.resolve("sim/src/test/resources/golden");

    static Stream<Arguments> cases() throws IOException {
        return GoldenTraceTest.cases();
    }

    @ParameterizedTest(name = "{0} with {1}")
    @MethodSource("cases")
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aWatchedRunWritesTheGoldenTrace(String arena, String controller) throws IOException {
        StringWriter out = new StringWriter();
        List<EngineEvent> events = new ArrayList<>();
        Simulation.builder().arena(REPO.resolve("arenas/" + arena + ".arena").toString()).controller(controller)
                .seed(1).seconds(60).sampleMillis(100).trace(out).events(events::add).run();
        String trace = out.toString().replace(REPO.toString(), "");
        Path golden = GOLDEN.resolve(arena + "-" + controller + ".trace");
        assertEquals(Files.readString(golden), trace, "watching the events changed the run of " + golden);
        // Every bundled arena has regions, and every robot starts in one: its entry is an event at 0.
        assertEquals(0, events.get(0).timeNanos(), events.toString());
    }
}
