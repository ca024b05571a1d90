package org.kheperasim.sim.host;

import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/**
 * The step watchdog's thread is started inside a step, with the step's clock bound to the thread:
 * it must not inherit it (the clock holds the step's host, and through it a whole run, which the
 * watchdog would keep for the life of the JVM).
 */
class StepWatchdogTest {

    @Test
    void theWatchdogsThreadInheritsNoClock() throws InterruptedException {
        // Any clock will do: the thread only looks whether it has one.
        SimClock.Clock clock = (SimClock.Clock) java.lang.reflect.Proxy.newProxyInstance(
                SimClock.Clock.class.getClassLoader(), new Class<?>[] {SimClock.Clock.class}, (proxy, method, args) -> null);
        AtomicReference<Object> seen = new AtomicReference<>("not run");
        SimClock.bind(clock);
        try {
            assertSame(clock, SimClock.current());
            Thread t = StepWatchdog.daemon(() -> seen.set(SimClock.current()), "probe");
            assertTrue(t.isDaemon());
            t.start();
            t.join(10_000);
            assertTrue(!t.isAlive() && !"not run".equals(seen.get()), "the probe thread did not run");
        } finally {
            SimClock.unbind();
        }
        assertNull(seen.get(), "the thread saw the clock of the thread that made it");
    }
}
