package org.kheperasim.sim.sandbox;

import java.util.ArrayList;
import java.util.List;

/**
 * The resource limits of a box, set with {@code prlimit} inside it (after its namespaces are made,
 * so that a user namespace counts only its own processes) on the user the box runs as. Why these
 * numbers is in docs/grading.md ("The sandbox").
 *
 * @param processes    processes and threads the box's user may have (RLIMIT_NPROC: every JVM thread
 *                     counts; a run's JVM has about 15 of its own)
 * @param openFiles    open files per process (RLIMIT_NOFILE)
 * @param cpuSeconds   CPU time of the JVM, all its threads together, s (RLIMIT_CPU), or 0 for none
 * @param memoryBytes  address space (RLIMIT_AS), bytes: the heap and what the JVM reserves besides,
 *                     which the box's JVM options keep small (see {@link #javaOptions})
 * @param fileBytes    the largest file the box may write, bytes (RLIMIT_FSIZE)
 * @param scratchBytes the size of the box's private scratch folder {@code /tmp}, bytes
 */
public record BoxLimits(int processes, int openFiles, long cpuSeconds, long memoryBytes, long fileBytes,
        long scratchBytes) {
    /** A JVM's own threads and the tools that start it, with room for a few controller threads each robot. */
    static final int BASE_PROCESSES = 48;
    /** The threads a warm worker JVM has besides a run's own JVM's. */
    static final int WORKER_THREADS = 2;
    private static final long MIB = 1L << 20;

    /**
     * The limits of one graded run.
     *
     * @param heapMb      the run's heap, MiB
     * @param robots      the robots of its arena (a thread-style controller each, with its helpers)
     * @param wallSeconds the run's wall-clock limit, s: its CPU time may be twice that (a busy run uses one
     *                    core, the JIT and the collector a little more)
     * @return the limits
     */
    public static BoxLimits forRun(int heapMb, int robots, double wallSeconds) {
        return new BoxLimits(BASE_PROCESSES + 4 * StrictMath.max(1, robots), 256,
                (long) StrictMath.ceil(2 * wallSeconds) + 30,
                (heapMb + 768L) * MIB, 64 * MIB, 64 * MIB);
    }

    /**
     * The limits of a warm worker's box, which makes several graded runs one after another: those of
     * one run ({@link #forRun}), with room for the worker's own two threads, but for the CPU time, which
     * RLIMIT_CPU counts for the whole process, so it is the runs' together (each run's own wall-clock
     * limit still ends it).
     *
     * @param heapMb      each run's heap, MiB (the worker holds one run at a time)
     * @param robots      the most robots of the arenas it runs in
     * @param wallSeconds each run's wall-clock limit, s
     * @param runs        the most runs it makes
     * @return the limits
     */
    public static BoxLimits forWorker(int heapMb, int robots, double wallSeconds, int runs) {
        BoxLimits one = forRun(heapMb, robots, wallSeconds);
        long cpu = (long) StrictMath.min(Long.MAX_VALUE / 4,
                StrictMath.ceil(2 * wallSeconds) * (double) StrictMath.max(1, runs) + 30);
        // The worker's own two threads (its requests, its wall-clock watch): a run has as many threads to spare as in
        // its own JVM.
        return new BoxLimits(one.processes() + WORKER_THREADS, one.openFiles(), cpu, one.memoryBytes(), one.fileBytes(),
                one.scratchBytes());
    }

    /**
     * The limits of a single {@code run --sandbox} or {@code serve --sandbox}: no CPU limit (a served
     * robot runs until it is stopped), a 1 GiB heap at most.
     *
     * @param robots the arena's robots
     * @return the limits
     */
    public static BoxLimits forCommand(int robots) {
        return new BoxLimits(BASE_PROCESSES + 4 * StrictMath.max(1, robots), 256, 0, (1024 + 768L) * MIB,
                256 * MIB, 256 * MIB);
    }

    /**
     * JVM options that keep what the JVM reserves (not uses) small enough for {@link #memoryBytes}: by
     * default a 256 MiB heap comes with 1 GiB of class space, 240 MiB of code cache and a 64 MiB
     * malloc arena per thread, about 3 GiB of address space that is never touched.
     *
     * @return the options
     */
    static List<String> javaOptions() {
        return List.of("-XX:CompressedClassSpaceSize=128m", "-XX:ReservedCodeCacheSize=64m",
                "-XX:MaxMetaspaceSize=160m",
                "-Xss1m");
    }

    /** @return {@code prlimit}'s options setting these limits, soft and hard alike */
    List<String> prlimitArgs() {
        List<String> out = new ArrayList<>();
        out.add("--nproc=" + processes);
        out.add("--nofile=" + openFiles);
        out.add("--as=" + memoryBytes);
        out.add("--fsize=" + fileBytes);
        out.add("--core=0");
        if (cpuSeconds > 0) {
            out.add("--cpu=" + cpuSeconds);
        }
        return out;
    }
}
