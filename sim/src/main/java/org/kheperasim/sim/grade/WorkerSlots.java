package org.kheperasim.sim.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import org.kheperasim.sim.arena.Arena;

/**
 * Makes a grading's runs on warm workers, {@code jobs} at once: each slot takes a submission no
 * worker has yet and makes its runs (its arenas × seeds, in the plan's order) on one worker JVM,
 * one after another; when every submission has its worker, a slot that would idle starts a second
 * worker on the submission with the most runs left (at least two), and the two take its runs
 * in turn. A worker is replaced when it cannot take another run ({@link WorkerProcess#ready}), and
 * after {@code workerRuns} runs.
 */
final class WorkerSlots {
    /** How long a worker may take to put its JVM back after a run (a full collection, its threads' end), ms. */
    private static final long READY_MILLIS = 60_000;

    /** What the grader does with a run made: its picture, page, journal line and progress. */
    @FunctionalInterface
    interface Finisher {
        void finish(GradePlan.Job job, ChildRun.Outcome outcome) throws IOException;
    }

    private final Map<String, Deque<GradePlan.Job>> pending = new LinkedHashMap<>();
    private final Map<String, Integer> workersOn = new HashMap<>();
    private final AtomicInteger folders = new AtomicInteger();
    private final AtomicInteger replaced = new AtomicInteger();
    private java.util.concurrent.atomic.AtomicBoolean stop = new java.util.concurrent.atomic.AtomicBoolean();

    /**
     * How the runs were made, for the grader's progress (never the report: it depends on the machine).
     *
     * @param runs     runs made
     * @param workers  worker JVMs started
     * @param replaced workers that could not take their submission's next run (a run ended, or was found to
     *                 have left something behind) and were replaced
     */
    record Summary(int runs, int workers, int replaced) {
        /** @return one line for the progress stream */
        String line() {
            return String.format(java.util.Locale.ROOT,
                    "made %d runs on %d worker JVMs (%d replaced after a run that ended"
                    + " its worker or left something behind)", runs, workers, replaced);
        }
    }

    private WorkerSlots(List<GradePlan.Job> todo) {
        for (GradePlan.Job j : todo) {
            pending.computeIfAbsent(j.student(), s -> new ArrayDeque<>()).add(j);
        }
    }

    /**
     * @param todo       the runs to make (of runnable submissions), in the plan's order
     * @param subs       the submissions by student
     * @param arenas     the arenas by name
     * @param lim        the limits
     * @param jobs       runs at once
     * @param workerRuns the most runs one worker makes
     * @param runs       where the runs' traces and logs go
     * @param sockets    a folder of the grader's own, for the workers' sockets and scratch folders
     * @param running    the processes going now (a signal to the grader kills them)
     * @param finisher   what is done with each run made
     * @param stop       once set (the grading's deadline passed, or it was told to stop), no further run is started
     * @return how they were made
     */
    static Summary makeAll(List<GradePlan.Job> todo, Map<String, Submission> subs, Map<String, Arena> arenas,
            ChildRun.Limits lim,
            int jobs, int workerRuns, Path runs, Path sockets, Set<Process> running, Finisher finisher,
            java.util.concurrent.atomic.AtomicBoolean stop) {
        WorkerSlots slots = new WorkerSlots(todo);
        slots.stop = stop;
        List<String> arenaNames = todo.stream().map(GradePlan.Job::arena).distinct().toList();
        int robots = arenaNames.stream().mapToInt(a -> arenas.get(a).robots().size()).max().orElse(1);
        ExecutorService pool = Executors.newFixedThreadPool(jobs);
        List<Future<?>> futures = new ArrayList<>();
        for (int i = 0; i < jobs; i++) {
            int slot = i;
            futures.add(pool.submit(() -> {
                String student;
                while ((student = slots.pick()) != null) {
                    try {
                        slots.work(student, subs.get(student), arenaNames, robots, arenas, lim, workerRuns,
                                slot, runs, sockets,
                                running, finisher);
                    } finally {
                        slots.release(student);
                    }
                }
                return null;
            }));
        }
        Grader.awaitAll(pool, futures);
        return new Summary(todo.size(), slots.folders.get(), slots.replaced.get());
    }

    /** Make a submission's runs (those this slot takes) on a worker, replaced as need be. */
    private void work(String student, Submission sub, List<String> arenaNames, int robots, Map<String, Arena> arenas,
            ChildRun.Limits lim, int workerRuns, int slot, Path runs, Path sockets, Set<Process> running,
            Finisher finisher)
            throws IOException {
        WorkerProcess w = null;
        try {
            GradePlan.Job job;
            while ((job = poll(student)) != null) {
                if (w != null && (w.runs() >= workerRuns || !w.ready(READY_MILLIS))) {
                    if (w.restartReason() != null) {
                        replaced.incrementAndGet();
                    }
                    w.close();
                    w = null;
                }
                if (w == null) {
                    Path folder = Files.createDirectories(sockets.resolve("w" + folders.incrementAndGet()));
                    w = WorkerProcess.start(sub, arenaNames, robots, lim,
                            StrictMath.min(workerRuns, left(student) + 1), slot,
                            folder, running);
                }
                ChildRun.Outcome made = w.run(job, sub, arenas.get(job.arena()), lim, runs);
                if (made.diverged() != null) {
                    // Made again once, on a worker JVM of its own: nothing of the first making's JVM carries over.
                    w.close();
                    w = null;
                    GradePlan.Job again = job;
                    WorkerProcess[] fresh = new WorkerProcess[1];
                    try {
                        made = Rerun.guard(made, () -> {
                            Path folder = Files.createDirectories(sockets.resolve("w" + folders.incrementAndGet()));
                            fresh[0] = WorkerProcess.start(sub, arenaNames, robots, lim, 1, slot, folder, running);
                            return fresh[0].run(again, sub, arenas.get(again.arena()), lim, runs);
                        });
                    } finally {
                        if (fresh[0] != null) {
                            fresh[0].close();
                        }
                    }
                }
                finisher.finish(job, made);
            }
        } finally {
            if (w != null) {
                w.close();
            }
        }
    }

    /**
     * @return a submission for a free slot: one no worker has yet, else a second worker's share of the most runs left,
     *     else null
     */
    private synchronized String pick() {
        if (stop.get()) {
            return null;
        }
        String most = null;
        for (Map.Entry<String, Deque<GradePlan.Job>> e : pending.entrySet()) {
            int on = workersOn.getOrDefault(e.getKey(), 0);
            if (e.getValue().isEmpty()) {
                continue;
            }
            if (on == 0) {
                workersOn.put(e.getKey(), 1);
                return e.getKey();
            }
            if (e.getValue().size() >= 2 && (most == null || e.getValue().size() > pending.get(most).size())) {
                most = e.getKey();
            }
        }
        if (most != null) {
            workersOn.merge(most, 1, Integer::sum);
        }
        return most;
    }

    private synchronized GradePlan.Job poll(String student) {
        return stop.get() ? null : pending.get(student).poll();
    }

    private synchronized int left(String student) {
        return pending.get(student).size();
    }

    private synchronized void release(String student) {
        workersOn.merge(student, -1, Integer::sum);
    }
}
