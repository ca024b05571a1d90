package org.kheperasim.sim.host;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.api.spi.ControllerException;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;

/** The time model and the controller's life: sleeping, busy loops, exceptions, hangs, stops. */
class LockstepTest {
    private final List<ConsoleLine> console = new CopyOnWriteArrayList<>();

    private RunResult run(String controller, double seconds, HostOptions options) {
        return Simulation.builder().arena("lab").controller("org.kheperasim.testcontrollers." + controller)
                .seed(5).seconds(seconds).console(console::add).hostOptions(options).run();
    }

    private RunResult run(String controller, double seconds) {
        return run(controller, seconds, HostOptions.defaults());
    }

    private String messages() {
        StringBuilder sb = new StringBuilder();
        console.forEach(l -> sb.append(l.format()).append('\n'));
        return sb.toString();
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void threadSleepAndTheClocksRunOnSimulatedTime() {
        RunResult r = run("Sleeper", 5);
        assertEquals(ControllerStatus.FINISHED, r.first().status());
        String text = messages();
        // Each clock call costs one API call (20 us); the sleeps cost exactly 1000 ms.
        assertTrue(text.contains("millis 1000 nanos 1000040000"), text);
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aBusyLoopOfApiCallsMovesTimeByTheCallCost() {
        run("BusyReader", 5);
        // 50,000 reads and the nanoTime call that opened the measurement, 20 us each.
        assertTrue(messages().contains("elapsed 1000020000 sum true"), messages());
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void theFriendlierBaseClassRunsItsLoopOnSimulatedTime() {
        RunResult r = run("Friendly", 10);
        assertEquals(ControllerStatus.FINISHED, r.first().status());
        assertTrue(messages().contains("setup at 60000"), messages());
        // setup: currentTimeMillis and print; each step: setSpeeds, proximity and the sleep.
        long expected = 2 * 20_000L + 8 * (2 * 20_000L + 250_000_000L);
        assertTrue(messages().contains("steps 8 at " + expected), messages());
        // cleanup() stopped the motors after the loop, and the run ended when the controller did.
        assertTrue(r.simulatedSeconds() < 2.1, "ended at " + r.simulatedSeconds());
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void anExceptionStopsTheRobotAndPointsAtTheStudentsLine() {
        RunResult r = run("Thrower", 30);
        assertEquals(ControllerStatus.FAILED, r.first().status());
        assertTrue(r.first().failure().contains("ArithmeticException"), r.first().failure());
        String text = messages();
        assertTrue(text.contains("ERROR Thrower: threw java.lang.ArithmeticException: / by zero"), text);
        assertTrue(text.contains("Thrower.run(Thrower.java:24)"), text);
        assertTrue(r.simulatedSeconds() < 1.1, "the run ends when its only controller has failed");
        double travelled = r.first().distanceMm();
        assertEquals(40.0, travelled, 2.0, "drove one second at 5 units, then stopped");
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aControllerThatStopsCallingTheApiIsReportedAndStopped() {
        HostOptions options = HostOptions.defaults().withHangTimeout(TimeUnit.MILLISECONDS.toNanos(500));
        RunResult r = run("Spinner", 20, options);
        assertEquals(ControllerStatus.HUNG, r.first().status());
        String text = messages();
        assertTrue(text.contains("controller Spinner (org.kheperasim.testcontrollers.Spinner) stopped making API calls"
                + " at simulated time 2.000"), text);
        assertTrue(r.first().distanceMm() < 2.1 * 32, "the motors were stopped: " + r.first().distanceMm());
        // The runaway loop itself was stopped (at its loop's back-edge), not left spinning.
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while (spinnerStillRunning() && System.nanoTime() < deadline) {
            Thread.onSpinWait();
        }
        assertTrue(!spinnerStillRunning(), "the hung controller's thread is still looping");
    }

    private static boolean spinnerStillRunning() {
        for (StackTraceElement[] stack : Thread.getAllStackTraces().values()) {
            for (StackTraceElement e : stack) {
                if (e.getClassName().equals("org.kheperasim.testcontrollers.Spinner")) {
                    return true;
                }
            }
        }
        return false;
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aControllerThatIgnoresInterruptionsIsStillStoppedAtTheEnd() {
        RunResult r = run("Forever", 3);
        assertEquals(ControllerStatus.STOPPED, r.first().status());
        assertEquals(3.0, r.simulatedSeconds(), 1e-9);
    }

    @Test
    void aClassWithoutTheControllerConstructorIsRefusedWithTheFix() {
        ControllerException e = assertThrows(ControllerException.class, () -> run("NoConstructor", 1));
        assertTrue(e.getMessage().contains("has no constructor NoConstructor(CurrentRobotState, MessagePasser)"), e.getMessage());
    }

    @Test
    void anUnknownControllerNamesTheBundledOnesAndTheFix() {
        ControllerException e = assertThrows(ControllerException.class,
                () -> Simulation.builder().arena("lab").controller("WallFolower").seconds(1).run());
        assertTrue(e.getMessage().contains("no controller named 'WallFolower'"), e.getMessage());
        assertTrue(e.getMessage().contains("did you mean WallFollower?"), e.getMessage());
        assertTrue(e.getMessage().contains("--controller WallFollower"), e.getMessage());
    }
}
