package org.kheperasim.sim.host;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.lang.management.ManagementFactory;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;

/**
 * Threads a controller starts take part in the lockstep on the simulated clock: they run one at
 * a time with the controller's own thread, sleep, wait, are notified, joined and interrupted in
 * simulated time, cannot block the run by holding a lock while they sleep, end with the controller,
 * and give the same trace twice even with random real-time delays at every hand-over.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ControllerThreadsTest {
    private final List<ConsoleLine> console = new CopyOnWriteArrayList<>();

    private RunResult run(String controller, double seconds, HostOptions options, StringWriter trace) {
        Simulation.Builder b = Simulation.builder().arena("lab").controller("org.kheperasim.testcontrollers." + controller)
                .seed(5).seconds(seconds).console(console::add).hostOptions(options);
        if (trace != null) {
            b.trace(trace);
        }
        return b.run();
    }

    private String messages() {
        StringBuilder sb = new StringBuilder();
        console.forEach(l -> sb.append(l.format()).append('\n'));
        return sb.toString();
    }

    private String line(String prefix) {
        for (ConsoleLine l : console) {
            if (l.text().startsWith(prefix)) {
                return l.text();
            }
        }
        return "(no line starting '" + prefix + "' in:\n" + messages() + ")";
    }

    @Test
    void aSensorManagerThreadAndTheControllerTakeTurnsInSimulatedTime() {
        RunResult r = run("SensorManager", 5, HostOptions.defaults(), null);
        String order = line("order ");
        // The reader, started by the constructor, first runs when the controller's thread first
        // gives up the turn (its first 20 ms sleep): both at the start, the controller first.
        assertTrue(order.startsWith("order M60000 R60000 M60020 M60040 R60053 M60061 "), order);
        // While the reader holds the lock (8 ms of each 53) the controller's thread waits for it,
        // in simulated time, instead of blocking the run; otherwise it steers every 20 ms.
        List<Integer> reads = new java.util.ArrayList<>();
        int lastSteer = -1;
        int delayed = 0;
        for (String e : order.substring("order ".length()).split(" ")) {
            int t = Integer.parseInt(e.substring(1)) - 60_000;
            if (e.charAt(0) == 'R') {
                reads.add(t);
                continue;
            }
            for (int rt : reads) {
                assertFalse(t > rt && t < rt + 8, "no steering inside a read's lock (" + rt + " ms): " + order);
            }
            if (lastSteer >= 0 && t - lastSteer > 21) {
                delayed++;
            }
            lastSteer = t;
        }
        assertEquals(List.of(0, 53, 106, 159), reads, "the reader ran every 53 ms: " + order);
        assertTrue(delayed >= 1, "the controller's thread waited for the lock at least once: " + order);
        assertTrue(r.first().distanceMm() > 100, "it drove: " + r.first());
        assertEquals(ControllerStatus.STOPPED, r.first().status(), messages());
        // At the end the controller's own thread unwinds, then the reader: neither is left behind.
        assertFalse(messages().contains("left behind"), messages());
    }

    @Test
    void waitNotifyJoinAndInterruptWorkOnTheSimulatedClock() {
        RunResult r = run("WaitNotify", 5, HostOptions.defaults(), null);
        assertEquals("alive true true", line("alive"), "started threads are alive before they first run");
        // Its code sees its own Thread object and interrupt flag, whichever thread runs the code.
        assertEquals("self true true", line("self "));
        assertEquals("interrupt flag true true false", line("interrupt flag"));
        assertEquals("sleeper flagged true", line("sleeper flagged"));
        assertEquals("sleeper is sleeper", line("sleeper is"));
        assertTrue(line("sleeper interrupted at ").matches("sleeper interrupted at 10[0-9]"), line("sleeper"));
        assertTrue(line("got 42 at ").matches("got 42 at 30[0-9]"), "woken by the producer's notify: " + line("got"));
        assertTrue(line("joined at ").matches("joined at 30[0-9] alive false false"), line("joined"));
        assertFalse(messages().contains("slept on"), messages());
        assertEquals(ControllerStatus.FINISHED, r.first().status(), messages());
        assertTrue(r.simulatedSeconds() < 0.5, "the run ended with its controller: " + r.simulatedSeconds());
    }

    /** The helper that was to notify the waiting controller ends without it: a deadlock, named at once. */
    @Test
    void aWaitThatTheEndedHelperWasToNotifyIsADeadlock() {
        RunResult r = run("AbandonedWaiter", 3, HostOptions.defaults(), null);
        assertTrue(line("controller AbandonedWaiter").contains("is deadlocked: the controller's own thread waits in wait()"),
                messages());
        assertEquals(ControllerStatus.HUNG, r.first().status(), messages());
        assertTrue(r.simulatedSeconds() < 0.1, "found when the helper ended: " + r.simulatedSeconds());
    }

    /**
     * The controller's run() returns while its sensor-manager thread holds the controller's monitor
     * and sleeps: its thread cannot finish ending until that monitor is free, yet it has returned.
     */
    @Test
    void aControllerThatReturnsWhileItsHelperHoldsItsLockHasFinished() {
        RunResult r = run("LockedAtReturn", 3, HostOptions.defaults(), null);
        assertEquals("returns", line("returns"), messages());
        assertEquals(ControllerStatus.FINISHED, r.first().status(), messages());
        assertFalse(messages().contains("stopped making API calls"), messages());
    }

    /** getState() tells what a platform thread would be doing, from the lockstep's own record. */
    @Test
    void getStateSaysWhatEachThreadIsDoing() {
        RunResult r = run("ThreadStates", 2, HostOptions.defaults(), null);
        assertEquals("states busy RUNNABLE sleeper TIMED_WAITING joiner WAITING", line("states busy"), messages());
        assertEquals("states waiter WAITING timed TIMED_WAITING notified BLOCKED", line("states waiter"), messages());
        assertEquals("states after TERMINATED TERMINATED TERMINATED", line("states after"), messages());
        assertEquals(ControllerStatus.FINISHED, r.first().status(), messages());
    }

    /** A constructor that reads the clock, its thread or takes a lock works, and sees the run's start. */
    @Test
    void aConstructorMayLookAtTheClockItsThreadAndALock() {
        RunResult r = run("LooksAround", 1, HostOptions.defaults(), null);
        assertEquals("seed " + ControllerClock.EPOCH_MILLIS + " constructed on a thread true runs as itself true",
                line("seed "), messages());
        assertEquals(ControllerStatus.FINISHED, r.first().status(), messages());
    }

    @Test
    void threadsThatWaitForEachOtherAreADeadlockNamedAndTheRobotStopped() {
        RunResult r = run("Deadlock", 3, HostOptions.defaults(), null);
        assertEquals(ControllerStatus.HUNG, r.first().status(), messages());
        String text = messages();
        assertTrue(text.contains("is deadlocked: the controller's own thread waits for a lock on a java.lang.Object"
                + " held by thread 'second'; thread 'second' waits for a lock on a java.lang.Object held by the"
                + " controller's own thread"), text);
        assertTrue(r.simulatedSeconds() < 0.1, "the run ended with its only controller: " + r.simulatedSeconds());
        assertTrue(r.first().distanceMm() < 5, "the robot was stopped at the deadlock (10 ms): " + r.first());
    }

    @Test
    void aThreadStartedByTheControllerEndsWithItAndLeavesNoThreadBehind() throws InterruptedException {
        int before = ManagementFactory.getThreadMXBean().getThreadCount();
        RunResult r = run("OutlivesMain", 5, HostOptions.defaults(), null);
        assertEquals(ControllerStatus.FINISHED, r.first().status(), messages());
        assertFalse(messages().contains("left behind"), messages());
        // 1 s at 2 units (16 mm/s): the thread's driving ended with the controller.
        assertEquals(16, r.first().distanceMm(), 3, r.first().toString());
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        int after;
        do {
            Thread.sleep(20);
            after = ManagementFactory.getThreadMXBean().getThreadCount();
        } while (after > before && System.nanoTime() < deadline);
        assertTrue(after <= before, "threads back to " + before + ", now " + after);
    }

    @Test
    void manyThreadsGiveTheSameTraceTwiceWithRandomDelaysAtEveryHandOver() {
        HostOptions jitter = HostOptions.defaults().withJitter(300);
        for (String c : List.of("SensorManager", "WaitNotify", "Deadlock")) {
            StringWriter first = new StringWriter();
            StringWriter second = new StringWriter();
            run(c, 3, jitter, first);
            String once = messages();
            console.clear();
            run(c, 3, jitter, second);
            assertEquals(first.toString(), second.toString(), c + ": the same trace");
            assertEquals(once.replaceAll("\\[[^]]*\\]", ""), messages().replaceAll("\\[[^]]*\\]", ""),
                    c + ": the same messages");
            console.clear();
        }
    }
}
