package org.kheperasim.sim.host;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryNotificationInfo;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.lang.management.MemoryUsage;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import javax.management.NotificationEmitter;

/**
 * Watches the Java heap for a controller that allocates without bound. The JVM itself tells when a
 * heap pool passes {@value #THRESHOLD_PERCENT} % of its maximum (a usage threshold, checked by its
 * low-memory detector), so a runaway controller is stopped before the heap runs out; the watchdog
 * also asks after each garbage collection how full the heap stayed. A small reserve is let go when
 * the heap runs short, so that reporting the fault still has room.
 */
final class HeapWatch {
    private static final int THRESHOLD_PERCENT = 80;
    private static final int FULL_PERCENT = 90;
    private static final List<Consumer<String>> LISTENERS = new CopyOnWriteArrayList<>();
    /**
     * Let go when the heap runs short, so that the fault can be reported and the run's result
     * printed while what the controller holds is still reachable: a sixteenth of the heap's maximum,
     * from 1 to 16 MB (a 64 MB heap keeps 4 MB).
     */
    private static volatile byte[] reserve = new byte[(int) StrictMath.max(1 << 20,
            StrictMath.min(16 << 20, Runtime.getRuntime().maxMemory() / 16))];
    /** The heap's memory pools, once {@link #watchPools} has set them up (none before). */
    private static volatile List<MemoryPoolMXBean> pools = List.of();
    private static final java.util.concurrent.CountDownLatch READY = new java.util.concurrent.CountDownLatch(1);

    static {
        // Setting up the pools' thresholds loads the JMX machinery, some tens of milliseconds: a
        // thread of its own does it while the run is being set up (arena, controller classes);
        // controllers start only when it is done (awaitReady).
        Thread setUp = new Thread(HeapWatch::watchPools, "heap-watch-set-up");
        setUp.setDaemon(true);
        setUp.start();
    }

    private HeapWatch() {
    }

    /** Start setting up the watch, if not yet (early, from the thread that sets a run up). */
    static void prepare() {
        // The class's initialisation starts the set-up; nothing more to do.
    }

    /** Wait until the watch is set up (before any controller code runs), at most a few seconds. */
    static void awaitReady() {
        try {
            READY.await(5, java.util.concurrent.TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static void watchPools() {
        try {
            setUpPools();
            // Reporting a fault and printing the result format numbers: load what that needs now,
            // beside the run's set-up, rather than when the heap may be full.
            String.format(Locale.ROOT, "%d %.1f %s", 1, 1.0, "");
        } finally {
            READY.countDown();
        }
    }

    private static void setUpPools() {
        // The pools that hold what lives on: the old generation (or a collector's single heap pool).
        // The young pools are left out: a survivor space is often full after a collection and an
        // eden space fills between any two, however little a controller keeps; neither supports a
        // usage threshold, which is how the JVM itself tells them apart.
        List<MemoryPoolMXBean> heap = ManagementFactory.getMemoryPoolMXBeans().stream()
                .filter(p -> p.getType() == MemoryType.HEAP && p.isUsageThresholdSupported()).toList();
        for (MemoryPoolMXBean pool : heap) {
            long max = pool.getUsage().getMax();
            if (max > 0) {
                pool.setUsageThreshold(max / 100 * THRESHOLD_PERCENT);
            }
        }
        pools = heap;
        if (ManagementFactory.getMemoryMXBean() instanceof NotificationEmitter emitter) {
            emitter.addNotificationListener((n, handback) -> {
                if (MemoryNotificationInfo.MEMORY_THRESHOLD_EXCEEDED.equals(n.getType())) {
                    // The reserve is kept for when the heap has really run out: let go at the mere
                    // threshold, it would only feed the controller until it is stopped.
                    String what;
                    try {
                        what = nearlyFull(THRESHOLD_PERCENT, false);
                    } catch (OutOfMemoryError e) {
                        reserve = null;
                        what = null;
                    }
                    for (Consumer<String> l : LISTENERS) {
                        l.accept(what != null ? what : "the heap passed " + THRESHOLD_PERCENT + " % of its maximum");
                    }
                }
            }, null, null);
        }
    }

    /** @param listener told (on a JVM service thread) when the heap passes its threshold */
    static void listen(Consumer<String> listener) {
        LISTENERS.add(listener);
    }

    /** @param listener no longer told */
    static void unlisten(Consumer<String> listener) {
        LISTENERS.remove(listener);
    }

    /** @return what is nearly full after the last garbage collection, for the user, or null when the heap is fine */
    static String nearlyFull() {
        return nearlyFull(FULL_PERCENT, true);
    }

    private static volatile long lastCollection;
    /** The heap's maximum (-Xmx), fixed for the JVM's life. */
    private static final long MAX_BYTES = Runtime.getRuntime().maxMemory();

    /**
     * A cheap look, for the controller's thread every few API calls: when the heap holds more than
     * the threshold, collect the garbage (at most five times a second) and look again.
     *
     * @return what is full, for the user, or null when the heap is fine
     */
    static String pressed() {
        Runtime rt = Runtime.getRuntime();
        long max = MAX_BYTES;
        // The heap the JVM holds bounds what is in use: while it is under the threshold, one call of
        // the JVM's answers (each costs a transition into the VM, and this runs every few API calls).
        long total = rt.totalMemory();
        if (total * 100 < max * THRESHOLD_PERCENT || (total - rt.freeMemory()) * 100 < max * THRESHOLD_PERCENT) {
            return null;
        }
        long now = System.nanoTime();
        if (now - lastCollection < 200_000_000L) {
            return null;
        }
        lastCollection = now;
        System.gc();
        long used = rt.totalMemory() - rt.freeMemory();
        return used * 100 < max * THRESHOLD_PERCENT ? null
                : String.format(Locale.ROOT, "%d of %d MB of the heap still in use after a garbage collection",
                        used >> 20, max >> 20);
    }

    /** The heap ran out: let the reserve go so that the fault can still be reported. */
    static void ranOut() {
        reserve = null;
    }

    private static String nearlyFull(int percent, boolean afterCollection) {
        for (MemoryPoolMXBean pool : pools) {
            MemoryUsage u = afterCollection ? pool.getCollectionUsage() : pool.getUsage();
            if (u != null && u.getMax() > 0 && u.getUsed() * 100 > u.getMax() * percent) {
                return String.format(Locale.ROOT, "the heap's %s was %d of %d MB full", pool.getName(),
                        u.getUsed() >> 20, u.getMax() >> 20);
            }
        }
        return null;
    }
}
