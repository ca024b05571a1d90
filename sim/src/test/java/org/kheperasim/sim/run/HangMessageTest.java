package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.host.HostOptions;

/**
 * A hung controller is told what it did: a {@code doWork()} that returns at once without a robot
 * call (an empty one, a student's first file) is not told about a loop it never wrote, and a loop
 * that waits without a call is.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class HangMessageTest {

    private static String hangMessage(String controller) {
        List<String> console = new ArrayList<>();
        RunResult r = Simulation.builder().arena("lab").controller(controller).seed(1).seconds(10)
                .hostOptions(HostOptions.defaults().withHangTimeout(TimeUnit.MILLISECONDS.toNanos(500)))
                .console((ConsoleLine line) -> {
                    synchronized (console) {
                        console.add(line.text());
                    }
                }).run();
        assertEquals(ControllerStatus.HUNG, r.first().status(), String.join("\n", console));
        synchronized (console) {
            return console.stream().filter(l -> l.contains("stopped making API calls")).findFirst().orElseThrow();
        }
    }

    @Test
    void anEmptyDoWorkIsToldItReturnsWithoutACallNotThatItLoops() {
        String m = hangMessage("org.kheperasim.testcontrollers.EmptyDoWork");
        assertTrue(m.contains("its doWork() returns without reading a sensor, setting a motor or sleeping"), m);
        assertTrue(m.contains("sleepMillis(100)"), m);
        assertTrue(m.contains("at simulated time 0.000 s"), m);
        assertFalse(m.contains("A loop that waits"), m);
    }

    @Test
    void aLoopInsideDoWorkIsToldAboutItsLoop() {
        String m = hangMessage("org.kheperasim.testcontrollers.Looper");
        assertTrue(m.contains("A loop that waits for something must read a sensor or call Thread.sleep inside it"), m);
        assertFalse(m.contains("returns without"), m);
    }
}
