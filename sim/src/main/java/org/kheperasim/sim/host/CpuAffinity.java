package org.kheperasim.sim.host;

import com.sun.jna.Library;
import com.sun.jna.Native;
import com.sun.jna.NativeLong;
import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Keeps the threads that take turns in one run on one core (Linux, through JNA's
 * {@code sched_setaffinity}).
 *
 * <p>Only one of them runs at a time, and each hand-over wakes a parked thread. When the woken
 * thread's core is idle, the operating system wakes that core too (on a virtual machine, a call into
 * the hypervisor): 20–60 µs a hand-over on a 2-core virtual machine, against 2–4 µs when the thread
 * that hands over and the thread woken share a core and one simply follows the other there. A
 * swarm of thread-style controllers hands over at every wake-up of every controller, so this is most
 * of its time (10 robots: about 400 simulated seconds per wall second spread over the cores, about
 * 1,000 on one; docs/swarms.md). The JVM's own threads and the run's owner stay free.
 *
 * <p>A run claims a core of its own: none that another run holds, in this JVM or, through a lock
 * file per core, in another process of the same user (a class graded in parallel child JVMs); when
 * every core is held, the run's threads are not pinned. A core other than the claiming thread's is
 * preferred (the owner, which watches the run, wakes every millisecond). When the run gives the
 * core back, every thread of the process still kept on it alone is let free again: a controller's
 * thread that was left behind, and any thread created by a pinned one (Linux hands a thread's cores
 * down to the threads it creates, such as a parallel stream's pool workers). Nothing a run computes
 * depends on any of this. Where the calls are not available (not Linux, JNA cannot load its library,
 * one core allowed), or with {@code -Dkheperasim.pinTurns=false}, nothing is pinned.
 */
final class CpuAffinity {
    /** The system property that turns pinning off ({@code false}). */
    static final String SWITCH = "kheperasim.pinTurns";
    /** {@code cpu_set_t}: 1,024 bits, as unsigned longs (so the bits are right on either byte order). */
    private static final int MASK_LONGS = 16;
    /** Set once {@link #prepare} has started the loading: later runs find it done or under way. */
    private static final java.util.concurrent.atomic.AtomicBoolean PREPARED =
            new java.util.concurrent.atomic.AtomicBoolean();

    private CpuAffinity() {
    }

    /** The C library's calls, bound on first use: a run with one controller never loads JNA. */
    interface LibC extends Library {
        int sched_getcpu();

        int sched_getaffinity(int pid, NativeLong size, long[] mask);

        int sched_setaffinity(int pid, NativeLong size, long[] mask);
    }

    /** A core held by a run of this JVM, and its lock file's lock (null where no file could be locked). */
    private record Claim(FileChannel channel, FileLock lock) {
    }

    /**
     * What the process may use, found once. Everything of JNA's is here, not in the outer class: the
     * first use of a JNA class loads its native library, which a run that pins nothing must not pay.
     */
    private static final class Cores {
        /** The mask's size for the calls (null where JNA did not load). */
        static final NativeLong MASK_BYTES;
        static final LibC LIBC;
        /** The cores this process may run on, ascending; empty when pinning is off or impossible. */
        static final int[] ALLOWED;
        /** {@link #ALLOWED} as a mask, to let a thread free again. */
        static final long[] ALLOWED_MASK = new long[MASK_LONGS];
        /** Why pinning is off, or null. */
        static final String WHY_NOT;
        /** Per core: the run of this JVM that holds it, or null. */
        static final Claim[] CLAIMS = new Claim[MASK_LONGS * 64];

        static {
            LibC libc = null;
            NativeLong size = null;
            int[] allowed = new int[0];
            String why = null;
            if ("false".equalsIgnoreCase(System.getProperty(SWITCH))) {
                why = "-D" + SWITCH + "=false";
            } else if (!System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux")) {
                why = "not Linux";
            } else {
                // JNA logs (with a stack trace) when it cannot unpack its library; the reason is kept here instead.
                Logger jnaLog = Logger.getLogger("com.sun.jna");
                Level was = jnaLog.getLevel();
                jnaLog.setLevel(Level.OFF);
                try {
                    size = new NativeLong(MASK_LONGS * 8L);
                    libc = Native.load("c", LibC.class);
                    libc.sched_getcpu();
                    if (libc.sched_getaffinity(0, size, ALLOWED_MASK) != 0) {
                        why = "sched_getaffinity failed";
                    } else {
                        allowed = bits(ALLOWED_MASK);
                        if (allowed.length < 2) {
                            why = "one core allowed";
                            allowed = new int[0];
                        }
                    }
                } catch (LinkageError | RuntimeException e) {
                    why = "JNA unavailable: " + e;
                    allowed = new int[0];
                } finally {
                    jnaLog.setLevel(was);
                }
            }
            MASK_BYTES = size;
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

    /**
     * Start loading the native calls on a thread of its own (a tenth of a second at a cold start),
     * while the run is being set up; {@link #claim} waits for it.
     */
    static void prepare() {
        if (PREPARED.getAndSet(true)) {
            return;
        }
        Thread t = new Thread(() -> {
            try {
                unavailable();
            } catch (LinkageError e) {
                // claim() finds the same and pins nothing
            }
        }, "khepera-sim core affinity");
        t.setDaemon(true);
        t.start();
    }

    /** @return null when threads can be pinned here, else why not (for the docs and tests) */
    static String unavailable() {
        return Cores.WHY_NOT;
    }

    /**
     * Claim a core for a run's threads, one no other run holds (see the class comment). Give it
     * back with {@link #release}.
     *
     * @return the core, or -1 when the run's threads are not to be pinned
     */
    static int claim() {
        try {
            if (Cores.LIBC == null) {
                return -1;
            }
            int here = Cores.LIBC.sched_getcpu();
            synchronized (Cores.CLAIMS) {
                for (int pass = 0; pass < 2; pass++) {
                    for (int cpu : Cores.ALLOWED) {
                        if ((cpu == here) == (pass == 0) || Cores.CLAIMS[cpu] != null) {
                            continue;
                        }
                        Claim c = lock(cpu);
                        if (c != null) {
                            Cores.CLAIMS[cpu] = c;
                            return cpu;
                        }
                    }
                }
            }
        } catch (LinkageError | RuntimeException e) {
            // Not worth failing a run over: its threads stay where the system puts them.
        }
        return -1;
    }

    /**
     * The core's lock file, locked; a claim without a file where none can be written; null when another process holds
     * it.
     */
    private static Claim lock(int cpu) {
        String user = System.getProperty("user.name", "user").replaceAll("[^A-Za-z0-9._-]", "_");
        Path dir = Path.of("/dev/shm");
        if (!Files.isDirectory(dir) || !Files.isWritable(dir)) {
            dir = Path.of(System.getProperty("java.io.tmpdir"));
        }
        FileChannel ch = null;
        try {
            ch = FileChannel.open(dir.resolve("kheperasim-" + user + "-core-" + cpu + ".lock"),
                    StandardOpenOption.CREATE, StandardOpenOption.WRITE);
            FileLock lock = ch.tryLock();
            if (lock == null) {
                ch.close();
                return null;
            }
            return new Claim(ch, lock);
        } catch (OverlappingFileLockException e) {
            close(ch);
            return null;
        } catch (IOException e) {
            close(ch);
            return new Claim(null, null);
        }
    }

    private static void close(FileChannel ch) {
        if (ch != null) {
            try {
                ch.close();
            } catch (IOException e) {
                // nothing held
            }
        }
    }

    /**
     * A run whose threads were kept on {@code cpu} has ended: every thread of the process still kept
     * on that core alone is let free (left-behind controller threads, threads they created), then
     * the core is given back.
     */
    static void release(int cpu) {
        if (cpu < 0 || Cores.LIBC == null) {
            return;
        }
        synchronized (Cores.CLAIMS) {
            Claim c = Cores.CLAIMS[cpu];
            if (c == null) {
                return;
            }
            try {
                freeThreadsKeptOn(cpu);
            } finally {
                Cores.CLAIMS[cpu] = null;
                close(c.channel);
            }
        }
    }

    private static void freeThreadsKeptOn(int cpu) {
        String only = String.valueOf(cpu);
        try (java.util.stream.Stream<Path> tasks = Files.list(Path.of("/proc/self/task"))) {
            for (Path task : (Iterable<Path>) tasks::iterator) {
                if (only.equals(allowedList(task.resolve("status")))) {
                    unpin(Long.parseLong(task.getFileName().toString()));
                }
            }
        } catch (IOException | RuntimeException e) {
            // A thread that ended meanwhile, or no /proc: nothing more can be done.
        }
    }

    /** @return the {@code Cpus_allowed_list} of a {@code /proc} status file, or null */
    static String allowedList(Path status) {
        try {
            for (String line : Files.readAllLines(status)) {
                if (line.startsWith("Cpus_allowed_list:")) {
                    return line.substring("Cpus_allowed_list:".length()).trim();
                }
            }
        } catch (IOException e) {
            // the thread has ended
        }
        return null;
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
        try {
            return Cores.LIBC.sched_setaffinity(0, Cores.MASK_BYTES, mask) == 0;
        } catch (LinkageError | RuntimeException e) {
            return false;
        }
    }

    /** @return the calling thread's id in the operating system, or -1 when it cannot be told */
    static long callingThreadId() {
        try {
            // "/proc/thread-self" links to "<pid>/task/<tid>".
            return Long.parseLong(Files.readSymbolicLink(Path.of("/proc/thread-self")).getFileName().toString());
        } catch (IOException | RuntimeException e) {
            return -1;
        }
    }

    /** Let thread {@code tid} of this process run on every core the process may use again (a hung controller's). */
    static void unpin(long tid) {
        if (Cores.LIBC == null || tid <= 0) {
            return;
        }
        try {
            Cores.LIBC.sched_setaffinity((int) tid, Cores.MASK_BYTES, Cores.ALLOWED_MASK.clone());
        } catch (LinkageError | RuntimeException e) {
            // it stays where it is
        }
    }
}
