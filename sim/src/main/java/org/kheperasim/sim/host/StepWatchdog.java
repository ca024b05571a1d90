package org.kheperasim.sim.host;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Set;
import java.util.WeakHashMap;

/**
 * Watches what controller code runs on a thread that cannot watch itself: a step controller's
 * {@code step()}, inline on the thread that holds the turn (often the run's owner), and a
 * controller's construction (its constructor and static initializers, on the thread building the
 * run). One daemon thread for the whole JVM looks at them every 100 ms of real time and has an
 * overdue one stopped. A step host is watched from its first step to its end, not registered at
 * every step (a swarm makes thousands of steps a second); one that is dropped without being stopped
 * is forgotten with it.
 */
final class StepWatchdog {
    /** Something the watchdog looks at. */
    interface Watched {
        /**
         * @param nowNanos {@link System#nanoTime()} now @return true when it was found overdue (and is being stopped)
         */
        boolean overdue(long nowNanos);
    }

    private static final Set<Watched> RUNNING =
            Collections.synchronizedSet(Collections.newSetFromMap(new WeakHashMap<>()));
    private static final long PERIOD_MILLIS = 100;
    private static Thread watcher;

    private StepWatchdog() {
    }

    static void watch(Watched w) {
        RUNNING.add(w);
        if (watcher == null) {
            start();
        }
    }

    static void unwatch(Watched w) {
        RUNNING.remove(w);
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
                List<Watched> watched;
                synchronized (RUNNING) {
                    watched = new ArrayList<>(RUNNING);
                }
                for (Watched w : watched) {
                    w.overdue(now);
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
