package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutionException;

/**
 * One slot of {@link WorkerSlots}: its submissions one after another, each on a worker JVM of its own, with
 * the grader's fixed costs beside the runs rather than between them.
 *
 * <ul>
 * <li>A run is judged ({@link Verdict}: the replay of its command log), drawn and journaled on the grader's
 * judging threads while the worker makes the submission's next run. Whether that next run may be made on
 * the same JVM depends on the verdict (a run whose result differed from its replay is made again on a JVM of
 * its own, and its worker is not used again): when it did differ, the next run's result is dropped unjudged
 * and that run is made again on a new worker, as it would have been had it waited for the verdict.</li>
 * <li>After its first run on a submission, the slot starts the worker of the next submission no worker has
 * yet (when that one is prepared), so that its JVM's start and warm-up go beside this submission's runs.
 * The two workers alive at once in a slot run in boxes of two users of their own (the slot's two lanes).</li>
 * </ul>
 */
final class SlotWork {
    /** How long a worker may take to put its JVM back after a run (a full collection, its threads' end), ms. */
    private static final long READY_MILLIS = 60_000;
    /** The most runs of a slot judged or drawn at once behind its runs. */
    private static final int BEHIND = 2;

    private final WorkerSlots slots;
    private final WorkerSlots.Context ctx;
    private final int slot;
    /** Which of the slot's two box users the current worker has. */
    private int lane;
    /** A worker started ahead for the slot's next submission, or null. */
    private Ahead ahead;
    private final Deque<CompletableFuture<?>> behind = new ArrayDeque<>();
    /** The last run of the slot's previous submission, its verdict awaited only after the next one's first run. */
    private InFlight deferred;

    /** A worker started ahead for a submission taken for this slot. */
    private record Ahead(String student, WorkerProcess worker) {
    }

    /** A run made, its judgement under way. */
    private record InFlight(GradePlan.Job job, Submission sub, CompletableFuture<ChildRun.Outcome> verdict) {
    }

    SlotWork(WorkerSlots slots, WorkerSlots.Context ctx, int slot) {
        this.slots = slots;
        this.ctx = ctx;
        this.slot = slot;
    }

    /** Make runs until none is left to take. */
    void go() throws IOException {
        try {
            while (true) {
                String student;
                WorkerProcess first = null;
                if (ahead != null) {
                    student = ahead.student();
                    first = ahead.worker();
                    ahead = null;
                    lane = 1 - lane;
                } else {
                    student = slots.pick();
                    if (student == null) {
                        break;
                    }
                }
                try {
                    work(student, first);
                } finally {
                    slots.release(student);
                }
            }
            settleDeferred(lane);
            awaitBehind(0);
        } finally {
            if (ahead != null) {
                ahead.worker().close();
                slots.release(ahead.student());
                ahead = null;
            }
        }
    }

    /** The box user of a worker on this lane: two per slot when there are few enough slots, else one. */
    private int boxSlot(int onLane) {
        return twoLanes() ? slot + onLane * ctx.jobs() : slot;
    }

    private boolean twoLanes() {
        return ctx.jobs() <= 128;
    }

    /** Make a submission's runs (those this slot takes) on a worker, replaced as need be. */
    private void work(String student, WorkerProcess started) throws IOException {
        Submission sub = ctx.subs().get(student);
        if (sub == null || !sub.runnable()) {
            slots.drop(student);
            return;
        }
        WorkerProcess w = started;
        InFlight prev = null;
        Deque<GradePlan.Job> again = new ArrayDeque<>();
        try {
            GradePlan.Job job;
            while ((job = again.isEmpty() ? slots.poll(student) : again.poll()) != null) {
                if (w != null && w.runs() > 0 && (w.runs() >= ctx.workerRuns() || !w.ready(READY_MILLIS))) {
                    if (w.restartReason() != null) {
                        slots.replacedOne();
                    }
                    w.close();
                    w = null;
                    settle(prev, lane);
                    prev = null;
                }
                if (w == null) {
                    w = slots.start(ctx, sub, slots.left(student) + again.size() + 1, boxSlot(lane));
                }
                awaitBehind(BEHIND);
                WorkerProcess.Received got = w.make(job, sub, ctx.lim(), ctx.runs());
                boolean back = !slots.stopped();
                // The previous submission's last run, judged meanwhile, made again if need be on the free lane.
                settleDeferred(1 - lane);
                startAhead();
                CompletableFuture<ChildRun.Outcome> verdict = judge(prev, got, sub, back);
                if (prev != null) {
                    ChildRun.Outcome p = await(prev.verdict());
                    if (p.diverged() != null) {
                        // Its worker is used no more: the run just made on it is made again on a new one.
                        await(verdict);
                        w.close();
                        w = null;
                        again.push(job);
                        rerun(prev.job(), p, sub, lane);
                        prev = null;
                        continue;
                    }
                }
                prev = new InFlight(job, sub, verdict);
            }
            if (w != null) {
                w.close();
                w = null;
            }
            deferred = prev;
            if (!twoLanes()) {
                settleDeferred(lane);
            }
        } finally {
            if (w != null) {
                w.close();
            }
        }
    }

    /**
     * The run's judgement on the judging threads, once the run before it on the same worker is judged: if that
     * one differed from its replay, this one is dropped (null) and made again. A run judged to differ is not
     * finished here: the slot makes it again first ({@link Rerun}).
     */
    private CompletableFuture<ChildRun.Outcome> judge(InFlight prev, WorkerProcess.Received got, Submission sub,
            boolean back) {
        CompletableFuture<ChildRun.Outcome> before =
                prev == null ? CompletableFuture.completedFuture(null) : prev.verdict();
        CompletableFuture<ChildRun.Outcome> verdict = before.thenApplyAsync(p -> {
            if (p != null && p.diverged() != null) {
                deleteQuietly(got.trace());
                deleteQuietly(got.child().log());
                return null;
            }
            ChildRun.Outcome o = WorkerProcess.judge(got, sub, ctx.arenas().get(got.job().arena()), ctx.lim());
            return o;
        }, ctx.judges());
        behind.add(verdict.thenAcceptAsync(o -> {
            if (o != null && o.diverged() == null) {
                finish(got.job(), o, back);
            }
        }, ctx.judges()));
        return verdict;
    }

    /**
     * Wait for a run's verdict; if it differed from its replay, make it again (its worker is closed) on a worker
     * of this lane (none alive on it).
     */
    private void settle(InFlight prev, int onLane) throws IOException {
        if (prev == null) {
            return;
        }
        ChildRun.Outcome p = await(prev.verdict());
        if (p.diverged() != null) {
            rerun(prev.job(), p, prev.sub(), onLane);
        }
    }

    private void settleDeferred(int onLane) throws IOException {
        InFlight d = deferred;
        deferred = null;
        settle(d, onLane);
    }

    /** Made again once, on a worker JVM of its own: nothing of the first making's JVM carries over. */
    private void rerun(GradePlan.Job job, ChildRun.Outcome first, Submission sub, int onLane) throws IOException {
        WorkerProcess[] fresh = new WorkerProcess[1];
        ChildRun.Outcome made;
        try {
            made = Rerun.guard(first, () -> {
                fresh[0] = slots.start(ctx, sub, 1, boxSlot(onLane));
                return fresh[0].run(job, sub, ctx.arenas().get(job.arena()), ctx.lim(), ctx.runs());
            });
        } finally {
            if (fresh[0] != null) {
                fresh[0].close();
            }
        }
        finish(job, made, !slots.stopped());
    }

    private void finish(GradePlan.Job job, ChildRun.Outcome outcome, boolean back) {
        slots.madeOne();
        try {
            ctx.finisher().finish(job, outcome, back);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * After this slot's first run of a submission: the worker of the next submission no worker has yet, started
     * now so that it is warm when this slot comes to it.
     */
    private void startAhead() throws IOException {
        if (ahead != null || !twoLanes()) {
            return;
        }
        String next = slots.pickAhead(ctx.subs());
        if (next == null) {
            return;
        }
        try {
            ahead = new Ahead(next, slots.start(ctx, ctx.subs().get(next), slots.left(next), boxSlot(1 - lane)));
        } catch (IOException | RuntimeException e) {
            slots.release(next);
            throw e;
        }
    }

    /** Wait until at most {@code most} of this slot's runs are still being judged or drawn. */
    private void awaitBehind(int most) throws IOException {
        while (!behind.isEmpty() && (behind.size() > most || behind.peek().isDone())) {
            await(behind.poll());
        }
    }

    private static <T> T await(CompletableFuture<T> f) throws IOException {
        try {
            return f.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("grading was interrupted", e);
        } catch (ExecutionException | CompletionException e) {
            Throwable c = e.getCause() instanceof CompletionException ce && ce.getCause() != null ? ce.getCause()
                    : e.getCause();
            if (c instanceof UncheckedIOException u) {
                throw u.getCause();
            }
            if (c instanceof IOException io) {
                throw io;
            }
            if (c instanceof RuntimeException r) {
                throw r;
            }
            if (c instanceof Error r) {
                throw r;
            }
            throw new IOException(c);
        }
    }

    private static void deleteQuietly(Path p) {
        if (p == null) {
            return;
        }
        try {
            Files.deleteIfExists(p);
        } catch (IOException e) {
            // left behind in the work folder
        }
    }
}
