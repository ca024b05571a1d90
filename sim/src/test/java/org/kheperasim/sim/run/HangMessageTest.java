package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.api.Parameters;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.testcontrollers.SlowEmptyDoWork;

/**
 * A hung controller is told what it did: a {@code doWork()} that returns at once without a robot
 * call (an empty one, a student's first file) is not told about a loop it never wrote, and a loop
 * that waits without a call is. Told so on a loaded machine too, where the controller's thread runs only
 * now and then: the simulator watches for its doWork() to come round for half the time it was stalled
 * (at most 1 s), not for a fixed 50 ms.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class HangMessageTest {

    private static String hangMessage(String controller) {
        return hangMessage(controller, Parameters.NONE, 500);
    }

    private static String hangMessage(String controller, Parameters parameters, long hangMillis) {
        List<String> console = new ArrayList<>();
        RunResult r = Simulation.builder().arena("lab").controller(controller).seed(1).seconds(10).parameters(parameters)
                .hostOptions(HostOptions.defaults().withHangTimeout(TimeUnit.MILLISECONDS.toNanos(hangMillis)))
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

    /**
     * A doWork() whose every round takes about 400 ms of real time without a robot call (here: sorting; on a
     * machine at load 30, an empty doWork() whose thread waits its turn looks the same): still told that its
     * doWork() returns without a call. Watching for 50 ms, the simulator told it about a loop it never wrote.
     */
    @Test
    void aDoWorkThatReturnsSlowlyWithoutACallIsToldSoNotThatItLoops() {
        int n = 1_000_000;
        long[] nanos = new long[3];
        for (int i = 0; i < nanos.length; i++) {
            double[] a = new double[n];
            long t0 = System.nanoTime();
            SlowEmptyDoWork.fillAndSort(a);
            nanos[i] = System.nanoTime() - t0;
        }
        java.util.Arrays.sort(nanos);
        int size = (int) StrictMath.min(20_000_000, StrictMath.max(n, n * 400e6 / nanos[1]));
        String m = hangMessage("org.kheperasim.testcontrollers.SlowEmptyDoWork",
                Parameters.of(java.util.Map.of("n", new double[] {size})), 2000);
        assertTrue(m.contains("its doWork() returns without reading a sensor, setting a motor or sleeping"),
                "rounds of " + size + " numbers, " + nanos[1] / 1e6 + " ms per million here: " + m);
    }

    @Test
    void aLoopInsideDoWorkIsToldAboutItsLoop() {
        String m = hangMessage("org.kheperasim.testcontrollers.Looper");
        assertTrue(m.contains("A loop that waits for something must read a sensor or call Thread.sleep inside it"), m);
        assertFalse(m.contains("returns without"), m);
    }

    /**
     * A hung doWork() that returns at once never reaches a robot call, where its thread could be asked to
     * stop: the simulator ends its doWork() loop itself (a field, no code of the controller's), so its
     * thread ends instead of spinning on a core for the rest of the JVM's life (in the window, every later
     * run; with virtual threads, a carrier lost for good, and every later run stalled).
     */
    @Test
    void aHungEmptyDoWorkLeavesNoThreadBehind() throws InterruptedException {
        hangMessage("org.kheperasim.testcontrollers.EmptyDoWork");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (alive("EmptyDoWork") && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        assertFalse(alive("EmptyDoWork"), "the hung controller's thread still runs after its run ended");
    }

    private static boolean alive(String name) {
        return Thread.getAllStackTraces().keySet().stream().anyMatch(t -> t.getName().equals(name) && t.isAlive());
    }
}
