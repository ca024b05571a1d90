package org.kheperasim.sim.grade.worker;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.stream.Stream;
import org.kheperasim.sim.host.loading.SharedControllers;

/**
 * A warm worker JVM's life: it makes one submission's graded runs one after another, each as a
 * graded child JVM would make it ({@code grade.GradedRun}, through {@link Launcher}), and
 * between runs puts the JVM back as the next run must find it, or ends itself to be replaced.
 *
 * <p>Each run gets what a JVM of its own would give it: its controller classes through fresh class
 * loaders (the table of shared stateless classes is emptied before it, so not even a checked-stateless
 * class of an earlier run is reused), its own command-log socket, its own wall-clock limit, a
 * thread named {@code main}, an empty scratch folder and a collected heap. After it, the worker goes on
 * only when nothing of the run is left: no thread of it alive after a grace period, the heap after a
 * full collection no fuller than after the warm-up by more than an eighth of its maximum, the scratch
 * folder back as it was; and only after a run that ended by handing over its result with no
 * controller stopped against its will (hung, broke a rule, exceeded memory: such a stop may leave
 * state behind, such as the heap watch's spent reserve). Otherwise it marks the restart and ends
 * (docs/grading.md, "Warm workers").
 *
 * <p>The end of its standard input (the grader done, or gone even by {@code kill -9}) ends it at
 * once, as a run's own wall-clock limit does.
 */
public final class WorkerLoop {
    /** The exit status of a graded run (in a worker or a JVM of its own) whose grader went away. */
    public static final int ORPHANED_EXIT = 125;
    /** The exit status of a graded run that ended itself at its wall-clock limit (as timeout(1)'s). */
    public static final int WALL_LIMIT_EXIT = 124;
    /** How long a run's threads may take to end after it, ms. */
    private static final long THREAD_GRACE_MILLIS = 2000;

    /**
     * Makes one run: a graded run with these arguments, in this JVM; returns the exit status its JVM would end with.
     */
    @FunctionalInterface
    public interface Launcher {
        /**
         * @param args the graded run's arguments
         * @return the exit status a graded run's JVM would end with
         */
        int run(List<String> args);
    }

    private final Launcher launcher;
    private final PrintStream err;
    private final Path scratch;
    private final String classpath;
    private final BlockingQueue<String> requests = new LinkedBlockingQueue<>();
    private Set<Thread> ownThreads;
    private Set<Path> ownFiles;
    private long heapAfterWarmUp;
    /** The JVM's numbering of unnamed threads, or null where it cannot be reset (then each run ends the worker). */
    private final ThreadNumbering numbering = ThreadNumbering.at();
    /** Where that numbering stands when a graded JVM starts its run. */
    private final int firstThreadNumber;

    private WorkerLoop(Launcher launcher, Path scratch, String classpath) {
        this.launcher = launcher;
        this.err = System.err;
        this.scratch = scratch;
        this.classpath = classpath;
        this.firstThreadNumber = numbering == null ? 0 : numbering.next();
    }

    /**
     * Serve the grader until its standard input ends; never returns.
     *
     * @param launcher  makes a run
     * @param scratch   the runs' working folder (the box's {@code /tmp}): emptied of what a run left after each
     * @param classpath the submission's classes: a request for others is refused
     * @param warmUp    a run of the simulator's own, made before the first request, so that the threads the
     *                  simulator starts once for all its runs are there before any run is watched
     */
    public static void serve(Launcher launcher, Path scratch, String classpath, Runnable warmUp) {
        new WorkerLoop(launcher, scratch, classpath).loop(warmUp);
    }

    private void loop(Runnable warmUp) {
        daemon("khepera-worker-requests", this::readRequests);
        daemon("khepera-worker-wall-limit", this::watchWallClock);
        try {
            warmUp.run();
        } catch (RuntimeException | LinkageError e) {
            err.println("khepera-sim: worker warm-up failed: " + e);
        }
        ownThreads = alive();
        ownFiles = files();
        heapAfterWarmUp = collectedHeap();
        while (true) {
            String line;
            try {
                line = requests.take();
            } catch (InterruptedException e) {
                Runtime.getRuntime().halt(ORPHANED_EXIT);
                return;
            }
            WorkerProtocol.Request req;
            try {
                req = WorkerProtocol.Request.parse(line);
            } catch (IllegalArgumentException e) {
                err.println("khepera-sim: error: " + e.getMessage());
                err.flush();
                Runtime.getRuntime().halt(2);
                return;
            }
            WorkerRun run = make(req);
            String why = run.restartReason() != null ? run.restartReason()
                    : numbering == null ? "this JDK's numbering of unnamed threads cannot be put back" : leftovers();
            WorkerProtocol.Mark next =
                    why == null ? new WorkerProtocol.Mark(WorkerProtocol.Kind.READY, req.token(), -1, 0, "")
                    : new WorkerProtocol.Mark(WorkerProtocol.Kind.RESTART, req.token(), -1, 0, why);
            err.println(next.line());
            err.flush();
            if (why != null) {
                Runtime.getRuntime().halt(0);
            }
        }
    }

    /** Make one run, on a thread of its own named as a JVM's first ({@code main}), as a child JVM would. */
    private WorkerRun make(WorkerProtocol.Request req) {
        WorkerRun run = new WorkerRun(req, err);
        int at = req.args().indexOf("--classpath");
        if (at < 0 || at + 1 >= req.args().size() || !req.args().get(at + 1).equals(classpath)) {
            err.println("khepera-sim: error: this worker makes runs of " + classpath + " only");
            err.flush();
            Runtime.getRuntime().halt(2);
        }
        // A fresh JVM has shared no stateless controller class yet, nor numbered an unnamed thread of a run.
        SharedControllers.forget();
        if (numbering != null) {
            numbering.set(firstThreadNumber);
        }
        int[] exit = {1};
        boolean[] returned = {false};
        err.println(new WorkerProtocol.Mark(WorkerProtocol.Kind.START, req.token(), req.index(), 0, "").line());
        err.flush();
        WorkerRun.setCurrent(run);
        Thread main = new Thread(null, () -> {
            exit[0] = launcher.run(req.args());
            returned[0] = true;
        }, "main", 0, false);
        main.start();
        try {
            main.join();
        } catch (InterruptedException e) {
            Runtime.getRuntime().halt(ORPHANED_EXIT);
        }
        WorkerRun.setCurrent(null);
        if (!run.isDone()) {
            // As a JVM whose run did not hand over its result ends: its log as it stands, its exit status
            // the command's (1 when an error left its main thread, as the java launcher's).
            run.abortLog();
            int status = returned[0] ? exit[0] : 1;
            run.done(status, null);
            if (!returned[0] || status != 2) {
                run.restartBecause("the run ended without handing over its result (exit status " + status + ")");
            }
        }
        return run;
    }

    /** @return why the JVM is not as the next run must find it, or null when it is */
    private String leftovers() {
        long deadline = System.nanoTime() + THREAD_GRACE_MILLIS * 1_000_000L;
        Set<Thread> left = alive();
        left.removeAll(ownThreads);
        while (!left.isEmpty() && System.nanoTime() < deadline) {
            sleep(20);
            left.removeIf(t -> !t.isAlive());
        }
        if (!left.isEmpty()) {
            return left.size() + " thread(s) of the run still alive " + THREAD_GRACE_MILLIS / 1000 + " s after it ("
                    + left.iterator().next().getName() + ")";
        }
        Set<Path> now = files();
        now.removeAll(ownFiles);
        try {
            for (Path p : now) {
                try (Stream<Path> s = Files.walk(p)) {
                    for (Path q : s.sorted(Comparator.reverseOrder()).toList()) {
                        Files.deleteIfExists(q);
                    }
                }
            }
        } catch (IOException e) {
            return "the run's files in the scratch folder could not be deleted: " + e.getMessage();
        }
        long used = collectedHeap();
        long max = Runtime.getRuntime().maxMemory();
        if (used - heapAfterWarmUp > max / 8) {
            return String.format(Locale.ROOT,
                    "the heap holds %d MiB after a full collection, %d MiB more than after the"
                    + " warm-up", used >> 20, (used - heapAfterWarmUp) >> 20);
        }
        return null;
    }

    private static long collectedHeap() {
        Runtime rt = Runtime.getRuntime();
        System.gc();
        return rt.totalMemory() - rt.freeMemory();
    }

    private Set<Path> files() {
        Set<Path> out = new HashSet<>();
        try (Stream<Path> s = Files.list(scratch)) {
            s.forEach(out::add);
        } catch (IOException e) {
            // no scratch folder to watch
        }
        return out;
    }

    private static Set<Thread> alive() {
        Set<Thread> out = new HashSet<>();
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.isAlive()) {
                out.add(t);
            }
        }
        return out;
    }

    private void readRequests() {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                requests.add(line);
            }
        } catch (IOException e) {
            // the pipe broke: the grader is gone as well
        }
        err.flush();
        Runtime.getRuntime().halt(ORPHANED_EXIT);
    }

    /** A run that passes its wall-clock limit ends the worker, as it would end its own JVM. */
    private void watchWallClock() {
        while (true) {
            sleep(100);
            WorkerRun run = WorkerRun.current();
            if (run != null && System.nanoTime() > run.deadlineNanos()) {
                err.println(String.format(Locale.ROOT,
                        "khepera-sim: error: the run passed its wall-clock limit of %.0f s"
                        + " and ends itself (exit status %d)", run.wallSeconds(), WALL_LIMIT_EXIT));
                err.flush();
                Runtime.getRuntime().halt(WALL_LIMIT_EXIT);
            }
        }
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static void daemon(String name, Runnable r) {
        Thread t = new Thread(null, r, name, 0, false);
        t.setDaemon(true);
        t.start();
    }
}
