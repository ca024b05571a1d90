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
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.kheperasim.sim.arena.Arena;

/**
 * Makes a grading's runs on warm workers, {@code jobs} at once: each slot takes a submission no
 * worker has yet and makes its runs (its arenas × seeds, in the plan's order) on one worker JVM,
 * one after another ({@link SlotWork}); when every submission has its worker, a slot that would idle
 * starts a second worker on the submission with the most runs left (at least two), and the two take its
 * runs in turn. A worker is replaced when it cannot take another run ({@link WorkerProcess#ready}), and
 * after {@code workerRuns} runs. The submissions are prepared meanwhile ({@link Compiling}): a slot waits
 * only for the one it takes, and skips one that cannot run (its records are written as it is prepared).
 */
final class WorkerSlots {
    /** What the grader does with a run made: its picture, page, journal line and progress. */
    @FunctionalInterface
    interface Finisher {
        /**
         * @param job      the run
         * @param outcome  what came back of it
         * @param cameBack true when it came back before the grading was told to stop (else the stop may have cut
         *                 it: it is no result of the student's and goes to no journal)
         * @throws IOException if its picture, page or journal line cannot be written
         */
        void finish(GradePlan.Job job, ChildRun.Outcome outcome, boolean cameBack) throws IOException;
    }

    /**
     * What every slot of a grading shares.
     *
     * @param subs       the submissions, being prepared
     * @param arenaNames the arenas of the runs
     * @param robots     the most robots of those arenas
     * @param arenas     the arenas by name
     * @param lim        the limits
     * @param jobs       runs at once
     * @param workerRuns the most runs one worker makes
     * @param runs       where the runs' traces and logs go
     * @param sockets    a folder of the grader's own, for the workers' sockets and scratch folders
     * @param running    the processes going now (a signal to the grader kills them)
     * @param finisher   what is done with each run made
     * @param judges     the threads that judge, draw and journal the runs made, beside the runs
     */
    record Context(Compiling subs, List<String> arenaNames, int robots, Map<String, Arena> arenas,
            ChildRun.Limits lim, int jobs, int workerRuns, Path runs, Path sockets, Set<Process> running,
            Finisher finisher, ExecutorService judges) {
    }

    private final Map<String, Deque<GradePlan.Job>> pending = new LinkedHashMap<>();
    private final Map<String, Integer> workersOn = new HashMap<>();
    private final AtomicInteger folders = new AtomicInteger();
    private final AtomicInteger replaced = new AtomicInteger();
    private final AtomicInteger made = new AtomicInteger();
    private final AtomicBoolean stop;

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

    private WorkerSlots(List<GradePlan.Job> todo, AtomicBoolean stop) {
        this.stop = stop;
        for (GradePlan.Job j : todo) {
            pending.computeIfAbsent(j.student(), s -> new ArrayDeque<>()).add(j);
        }
    }

    /**
     * @param todo       the runs to make, in the plan's order (those of a submission that cannot run are skipped)
     * @param subs       the submissions, being prepared
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
    static Summary makeAll(List<GradePlan.Job> todo, Compiling subs, Map<String, Arena> arenas,
            ChildRun.Limits lim,
            int jobs, int workerRuns, Path runs, Path sockets, Set<Process> running, Finisher finisher,
            AtomicBoolean stop) {
        WorkerSlots slots = new WorkerSlots(todo, stop);
        List<String> arenaNames = todo.stream().map(GradePlan.Job::arena).distinct().toList();
        int robots = arenaNames.stream().mapToInt(a -> arenas.get(a).robots().size()).max().orElse(1);
        ExecutorService pool = Executors.newFixedThreadPool(jobs);
        ExecutorService judges = Executors.newFixedThreadPool(jobs, r -> {
            Thread t = new Thread(r, "grade-judge");
            t.setDaemon(true);
            return t;
        });
        Context ctx = new Context(subs, arenaNames, robots, arenas, lim, jobs, workerRuns, runs, sockets, running,
                finisher, judges);
        List<Future<?>> futures = new ArrayList<>();
        for (int i = 0; i < jobs; i++) {
            SlotWork slot = new SlotWork(slots, ctx, i);
            futures.add(pool.submit(() -> {
                slot.go();
                return null;
            }));
        }
        try {
            Grader.awaitAll(pool, futures);
        } finally {
            judges.shutdownNow();
        }
        return new Summary(slots.made.get(), slots.folders.get(), slots.replaced.get());
    }

    /**
     * Start a worker for a submission.
     *
     * @param ctx     the grading's
     * @param sub     the submission (runnable)
     * @param runs    the most runs it will make
     * @param boxSlot which of the grader's concurrent workers it is (its box's user)
     * @return the worker, starting
     * @throws IOException if it cannot be started
     */
    WorkerProcess start(Context ctx, Submission sub, int runs, int boxSlot) throws IOException {
        Path folder = Files.createDirectories(ctx.sockets().resolve("w" + folders.incrementAndGet()));
        return WorkerProcess.start(sub, ctx.arenaNames(), ctx.robots(), ctx.lim(),
                StrictMath.min(ctx.workerRuns(), runs), boxSlot, folder, ctx.running());
    }

    /** @return true once the grading was told to stop */
    boolean stopped() {
        return stop.get();
    }

    /** Counts a worker replaced after a run that ended it or left something behind. */
    void replacedOne() {
        replaced.incrementAndGet();
    }

    /** Counts a run made (its first making). */
    void madeOne() {
        made.incrementAndGet();
    }

    /**
     * @return a submission for a free slot: one no worker has yet, else a second worker's share of the most runs left,
     *     else null
     */
    synchronized String pick() {
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

    /**
     * @param subs the submissions, being prepared
     * @return the next submission no worker has yet, if it is prepared and can run (taken for a worker started
     *     ahead), else null; one prepared that cannot run is passed over (it needs no run)
     */
    synchronized String pickAhead(Compiling subs) {
        if (stop.get()) {
            return null;
        }
        for (Map.Entry<String, Deque<GradePlan.Job>> e : pending.entrySet()) {
            if (e.getValue().isEmpty() || workersOn.getOrDefault(e.getKey(), 0) != 0) {
                continue;
            }
            if (!subs.isDone(e.getKey())) {
                return null;
            }
            Submission sub = subs.get(e.getKey());
            if (sub == null) {
                return null;
            }
            if (!sub.runnable()) {
                e.getValue().clear();
                continue;
            }
            workersOn.put(e.getKey(), 1);
            return e.getKey();
        }
        return null;
    }

    synchronized GradePlan.Job poll(String student) {
        return stop.get() ? null : pending.get(student).poll();
    }

    /** Passes over the runs left of a submission that cannot run (its records are written as it is prepared). */
    synchronized void drop(String student) {
        pending.get(student).clear();
    }

    synchronized int left(String student) {
        return pending.get(student).size();
    }

    synchronized void release(String student) {
        workersOn.merge(student, -1, Integer::sum);
    }
}
