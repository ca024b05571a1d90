package org.kheperasim.sim.host.loading;

import java.lang.ref.ReferenceQueue;
import java.lang.ref.WeakReference;
import org.kheperasim.sim.host.MonitorStandIn;

/**
 * One controller class loader's own monitors for the objects its code does not own (see
 * {@link MonitorHooks}): an interned string literal, a {@code Class} object of the API or the
 * platform, an enum constant, a boxed value from the JVM's cache, any object of a class the
 * simulator or the platform defines. Such an object is one object for the whole JVM, so a robot
 * holding its monitor (while it sleeps, say) would block every other robot that locks it; the
 * controller's code locks, waits on and notifies a stand-in instead, one per object and loader,
 * the same for all of that loader's threads. A controller's loader is its robot's own (each robot
 * of each run gets one; a shared stateless controller takes no locks, see {@link StatelessCheck}),
 * so each robot locks its own stand-ins, and mutual exclusion among a robot's own threads holds as
 * before.
 *
 * <p>An object of a class the loader defines itself (the controller's objects, its lambdas, arrays
 * of its types, the {@code Class} objects of its classes) is its own: it keeps its own monitor.
 * The table holds its objects weakly (by identity), and dies with its loader, so nothing stays
 * from one run to the next.
 */
final class Monitors {
    private final ClassLoader owner;
    private final ReferenceQueue<Object> gone = new ReferenceQueue<>();
    private Entry[] table = new Entry[16];
    private int size;

    /** @param owner the loader whose code locks through this table */
    Monitors(ClassLoader owner) {
        this.owner = owner;
    }

    /** The object a stand-in takes the place of, for the lockstep's messages: only its type. */
    static final class StandIn implements MonitorStandIn {
        private final Monitors table;
        private final String type;

        private StandIn(Monitors table, String type) {
            this.table = table;
            this.type = type;
        }

        @Override
        public String standsForType() {
            return type;
        }

        @Override
        public String toString() {
            return "the controller's own monitor for a " + type;
        }
    }

    /**
     * @param monitor an object that controller code locks, waits on or notifies (not null)
     * @return {@code monitor} itself when the loader's code owns it, else the loader's stand-in for it
     */
    Object of(Object monitor) {
        if (isOwn(monitor)) {
            return monitor;
        }
        return standIn(monitor);
    }

    private boolean isOwn(Object monitor) {
        if (monitor.getClass().getClassLoader() == owner) {
            return true;
        }
        if (monitor instanceof StandIn s) {
            return s.table == this;
        }
        return monitor instanceof Class<?> c && c.getClassLoader() == owner;
    }

    /**
     * @param monitor an object, or a stand-in
     * @return the binary name of the type of the object a stand-in stands for, else of {@code monitor}'s own type
     */
    static String typeName(Object monitor) {
        return MonitorStandIn.typeName(monitor);
    }

    private synchronized Object standIn(Object monitor) {
        expunge();
        int hash = System.identityHashCode(monitor);
        int at = hash & (table.length - 1);
        for (Entry e = table[at]; e != null; e = e.next) {
            if (e.get() == monitor) {
                return e.standIn;
            }
        }
        StandIn s = new StandIn(this, monitor.getClass().getName());
        table[at] = new Entry(monitor, gone, hash, s, table[at]);
        if (++size > table.length - (table.length >> 2)) {
            grow();
        }
        return s;
    }

    /** @return how many objects have a stand-in now (for tests) */
    synchronized int size() {
        expunge();
        return size;
    }

    private void grow() {
        Entry[] old = table;
        table = new Entry[old.length * 2];
        for (Entry head : old) {
            for (Entry e = head; e != null;) {
                Entry next = e.next;
                int at = e.hash & (table.length - 1);
                e.next = table[at];
                table[at] = e;
                e = next;
            }
        }
    }

    /** Drop the entries of objects that are gone. */
    private void expunge() {
        for (Object r; (r = gone.poll()) != null;) {
            Entry dead = (Entry) r;
            int at = dead.hash & (table.length - 1);
            Entry prev = null;
            for (Entry e = table[at]; e != null; prev = e, e = e.next) {
                if (e == dead) {
                    if (prev == null) {
                        table[at] = e.next;
                    } else {
                        prev.next = e.next;
                    }
                    size--;
                    break;
                }
            }
        }
    }

    private static final class Entry extends WeakReference<Object> {
        final int hash;
        final StandIn standIn;
        Entry next;

        Entry(Object key, ReferenceQueue<Object> queue, int hash, StandIn standIn, Entry next) {
            super(key, queue);
            this.hash = hash;
            this.standIn = standIn;
            this.next = next;
        }
    }
}
