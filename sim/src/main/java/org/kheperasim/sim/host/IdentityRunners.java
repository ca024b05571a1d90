package org.kheperasim.sim.host;

import java.lang.ref.WeakReference;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The thread that runs each controller {@code Thread} object's code, where that is another thread
 * (see {@link ThreadRunners}): found by the object's identity, never by its {@code hashCode} or
 * {@code equals}, which are the student's to override; weak both ways, so a run's threads are
 * forgotten with it. Thread-safe.
 */
final class IdentityRunners {
    /** One object and the thread running its code, both weakly held. */
    private record Entry(WeakReference<Thread> object, WeakReference<Thread> runner) {
    }

    private final Map<Integer, List<Entry>> byHash = new HashMap<>();
    private int puts;
    /** False until the first put: most JVMs never make a runner, and pay one volatile read per look-up. */
    private volatile boolean used;

    /** Remember that {@code runner} runs {@code object}'s code. */
    synchronized void put(Thread object, Thread runner) {
        used = true;
        if ((++puts & 255) == 0) {
            byHash.values().removeIf(l -> {
                l.removeIf(e -> e.object().get() == null || e.runner().get() == null);
                return l.isEmpty();
            });
        }
        byHash.computeIfAbsent(System.identityHashCode(object), h -> new ArrayList<>(1))
                .add(new Entry(new WeakReference<>(object), new WeakReference<>(runner)));
    }

    /** @return the thread running {@code object}'s code, or null when it has none of its own */
    Thread get(Thread object) {
        if (!used) {
            return null;
        }
        synchronized (this) {
            return find(object);
        }
    }

    private Thread find(Thread object) {
        List<Entry> l = byHash.get(System.identityHashCode(object));
        if (l == null) {
            return null;
        }
        for (Entry e : l) {
            if (e.object().get() == object) {
                return e.runner().get();
            }
        }
        return null;
    }
}
