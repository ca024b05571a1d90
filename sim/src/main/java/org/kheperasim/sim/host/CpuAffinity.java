package org.kheperasim.sim.host;

import com.sun.jna.Library;
import com.sun.jna.Native;
import com.sun.jna.NativeLong;

/**
 * Keeps the threads that take turns in one run on one core (Linux, through JNA's
 * {@code sched_setaffinity}).
 *
 * <p>Only one of them runs at a time, and each hand-over wakes a parked thread. When the woken
 * thread's core is idle, the operating system wakes that core (on a virtual machine, a call into the
 * hypervisor): 20–60 µs a hand-over on a 2-core virtual machine, against 2–4 µs when the thread
 * that hands over and the thread woken share a core and one simply follows the other there. A
 * swarm of thread-style controllers hands over at every wake-up of every controller, so this is most
 * of its time: 10 robots ran about 375 simulated seconds per wall second spread over the cores and
 * about 1,000 kept on one (docs/swarms.md). The JVM's own threads (the compilers, the collector)
 * and the run's owner stay free to use the other cores.
 *
 * <p>Each run claims a core for its threads: the least used by the runs of this JVM that hold one
 * now, preferring the core the claiming thread is on. Where the call is not available (not Linux,
 * JNA cannot load its library, one core allowed) or {@code -Dkheperasim.pinTurns=false} is set,
 * nothing is pinned and threads hand over as before; nothing a run computes depends on it.
 */
final class CpuAffinity {
    /** The system property that turns pinning off ({@code false}). */
    static final String SWITCH = "kheperasim.pinTurns";
    /** {@code cpu_set_t}: 1,024 bits, as unsigned longs (so the bits are right on either byte order). */
    private static final int MASK_LONGS = 16;

    private CpuAffinity() {
    }

    /** The C library's calls, bound on first use: a run with one controller thread never loads JNA. */
    interface LibC extends Library {
        int sched_getcpu();

        int sched_getaffinity(int pid, NativeLong size, long[] mask);

        int sched_setaffinity(int pid, NativeLong size, long[] mask);
    }

    /** What the process may use, found once. */
    private static final class Cores {
        static final LibC LIBC;
        /** The cores this process may run on, ascending; empty when pinning is off or impossible. */
        static final int[] ALLOWED;
        /** Why pinning is off, or null. */
        static final String WHY_NOT;
        /** Per core: runs of this JVM whose threads are kept on it now. */
        static final int[] CLAIMS = new int[MASK_LONGS * 64];

        static {
            LibC libc = null;
            int[] allowed = new int[0];
            String why = null;
            if ("false".equalsIgnoreCase(System.getProperty(SWITCH))) {
                why = "-D" + SWITCH + "=false";
            } else if (!System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux")) {
                why = "not Linux";
            } else {
                try {
                    libc = Native.load("c", LibC.class);
                    long[] mask = new long[MASK_LONGS];
                    if (libc.sched_getaffinity(0, new NativeLong(MASK_LONGS * 8L), mask) != 0) {
                        why = "sched_getaffinity failed";
                    } else {
                        allowed = bits(mask);
                        if (allowed.length < 2) {
                            why = "one core allowed";
                            allowed = new int[0];
                        }
                    }
                } catch (LinkageError | RuntimeException e) {
                    why = "JNA unavailable: " + e;
                    libc = null;
                }
            }
            LIBC = allowed.length == 0 ? null : libc;
            ALLOWED = allowed;
            WHY_NOT = why;
        }

        private static int[] bits(long[] mask) {
            int n = 0;
            for (long m : mask) {
                n += Long.bitCount(m);
            }
            int[] out = new int[n];
            int k = 0;
            for (int i = 0; i < mask.length * 64; i++) {
                if ((mask[i >> 6] >>> (i & 63) & 1) != 0) {
                    out[k++] = i;
                }
            }
            return out;
        }
    }

    /** @return null when threads can be pinned here, else why not (for the docs and tests) */
    static String unavailable() {
        return Cores.WHY_NOT;
    }

    /**
     * Claim a core for a run's threads: of the cores this process may use, one held by the fewest
     * runs of this JVM, the calling thread's own on a tie. Give it back with {@link #release}.
     *
     * @return the core, or -1 when nothing is to be pinned
     */
    static int claim() {
        if (Cores.LIBC == null) {
            return -1;
        }
        int here = Cores.LIBC.sched_getcpu();
        synchronized (Cores.CLAIMS) {
            int best = -1;
            for (int cpu : Cores.ALLOWED) {
                if (best < 0 || Cores.CLAIMS[cpu] < Cores.CLAIMS[best]
                        || Cores.CLAIMS[cpu] == Cores.CLAIMS[best] && cpu == here) {
                    best = cpu;
                }
            }
            Cores.CLAIMS[best]++;
            return best;
        }
    }

    /** A run whose threads were kept on {@code cpu} has ended. */
    static void release(int cpu) {
        if (cpu < 0) {
            return;
        }
        synchronized (Cores.CLAIMS) {
            Cores.CLAIMS[cpu] = StrictMath.max(0, Cores.CLAIMS[cpu] - 1);
        }
    }

    /**
     * Keep the calling thread on {@code cpu} from now on.
     *
     * @param cpu a core from {@link #claim}
     * @return true when it is pinned
     */
    static boolean pinCallingThread(int cpu) {
        if (Cores.LIBC == null || cpu < 0) {
            return false;
        }
        long[] mask = new long[MASK_LONGS];
        mask[cpu >> 6] = 1L << (cpu & 63);
        return Cores.LIBC.sched_setaffinity(0, new NativeLong(MASK_LONGS * 8L), mask) == 0;
    }
}
