package org.kheperasim.sim.host;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Set;
import java.util.WeakHashMap;

/**
 * Watches the steps that run inline: a step controller's {@code step()} runs on the thread that
 * holds the turn (often the run's owner, which cannot watch itself), so one daemon thread for the
 * whole JVM looks at the step hosts every 100 ms of real time and has an overdue step stopped. A host
 * is watched from its first step to its end, not registered at every step (a swarm makes thousands
 * of steps a second); one that is dropped without being stopped is forgotten with it.
 */
final class StepWatchdog {
    private static final Set<StepHost> RUNNING = Collections.synchronizedSet(Collections.newSetFromMap(new WeakHashMap<>()));
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
        Thread t = daemon(() -> {
            while (true) {
                try {
                    Thread.sleep(PERIOD_MILLIS);
                } catch (InterruptedException e) {
                    return;
                }
                long now = System.nanoTime();
                List<StepHost> hosts;
                synchronized (RUNNING) {
                    hosts = new ArrayList<>(RUNNING);
                }
                for (StepHost h : hosts) {
                    h.overdue(now);
                }
            }
        }, "khepera-step-watchdog");
        t.start();
        watcher = t;
    }

    /**
     * A daemon thread that inherits no thread-local values: it is started inside a step, whose
     * simulated clock (an inheritable thread-local, holding the step's host and through it the
     * whole run) it would otherwise keep for the life of the JVM.
     */
    static Thread daemon(Runnable work, String name) {
        Thread t = new Thread(null, work, name, 0, false);
        t.setDaemon(true);
        return t;
    }
}
