package org.kheperasim.sim.host;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Watches the steps that run inline: a step controller's {@code step()} runs on the thread that
 * holds the turn (often the run's owner, which cannot watch itself), so one daemon thread for the
 * whole JVM looks at the running steps every 100 ms of real time and has an overdue one stopped.
 */
final class StepWatchdog {
    private static final Set<StepHost> RUNNING = ConcurrentHashMap.newKeySet();
    private static final long PERIOD_MILLIS = 100;
    private static Thread watcher;

    private StepWatchdog() {
    }

    static void watch(StepHost host) {
        RUNNING.add(host);
        if (watcher == null) {
            start();
        }
    }

    static void unwatch(StepHost host) {
        RUNNING.remove(host);
    }

    private static synchronized void start() {
        if (watcher != null) {
            return;
        }
        Thread t = new Thread(() -> {
            while (true) {
                try {
                    Thread.sleep(PERIOD_MILLIS);
                } catch (InterruptedException e) {
                    return;
                }
                long now = System.nanoTime();
                for (StepHost h : RUNNING) {
                    h.overdue(now);
                }
            }
        }, "khepera-step-watchdog");
        t.setDaemon(true);
        t.start();
        watcher = t;
    }
}
