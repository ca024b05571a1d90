package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
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

    /**
     * Robots whose controllers loop without an API call (in a thread of their own, or in a step): a stop
     * request asks the one holding the turn (or the step running) to stop at its next loop, so the run ends long before the hang timeout would take each off in
     * turn (here 60 s of real time per robot).
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"Looper", "StepLooper"})
    void aStopRequestEndsARunWhoseControllersLoopWithoutWaitingForTheHangTimeout(String looper) {
        long asked = System.nanoTime() + 500_000_000L;
        RunResult r = Simulation.builder().arena(MultiRobotTest.crowd(3)).controller("org.kheperasim.testcontrollers." + looper)
                .seed(1).seconds(100).hostOptions(org.kheperasim.sim.host.HostOptions.defaults().withHangTimeout(60_000_000_000L))
                .stopWhen(() -> System.nanoTime() > asked).run();
        assertEquals(3, r.robots().size());
        // Generous: a busy machine may take a while, but not the 60 s a hang would.
        assertTrue(r.wallSeconds() < 45, "the run ended " + r.wallSeconds() + " s after it began");
        for (RunResult.RobotResult robot : r.robots()) {
            assertEquals(org.kheperasim.sim.host.ControllerStatus.STOPPED, robot.status(), robot.name());
        }
    }
}
