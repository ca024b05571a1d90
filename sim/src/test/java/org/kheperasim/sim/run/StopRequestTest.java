package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A stop request (what SIGTERM or Ctrl-C makes) ends a headless run soon after it is made, whatever
 * style its controller has: with a thread-style controller the run's owner sees it while it watches;
 * with only step controllers nobody watches, and the world's own stepping must see it.
 */
class StopRequestTest {
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"Braitenberg", "StepBraitenberg"})
    void aStopRequestEndsTheRunSoonAfter(String controller) {
        AtomicBoolean stop = new AtomicBoolean();
        RunResult r = Simulation.builder().arena("lab").controller(controller).seed(1).seconds(100_000)
                .listener(s -> {
                    if (s.timeSeconds() >= 10) {
                        stop.set(true);
                    }
                }, 100)
                .stopWhen(stop::get).run();
        assertTrue(r.simulatedSeconds() >= 10 && r.simulatedSeconds() < 11,
                controller + ": asked to stop at 10 s of 100,000, it ran " + r.simulatedSeconds() + " s");
    }
}
