package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * The submissions of a grading, prepared ({@link Submissions#prepare}) one after another in the plan's
 * order on a thread of their own while the first runs go: a slot asks for the submission it is to run
 * and waits only for that one. What is done with a submission that cannot run (its runs' records: it
 * needs no run) is done on that thread as soon as it is known. Once the grading is told to stop (its
 * deadline passed), no further submission is prepared: its runs are not made.
 */
final class Compiling implements AutoCloseable {
    /** What is done with a submission once it is prepared, on the compiling thread. */
    @FunctionalInterface
    interface Prepared {
        void prepared(Submission sub) throws IOException;
    }

    private final Map<String, CompletableFuture<Submission>> subs = new LinkedHashMap<>();
    private final ExecutorService thread = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "grade-compile");
        t.setDaemon(true);
        return t;
    });

    /**
     * Starts preparing.
     *
     * @param folders  the student folders, in the plan's order
     * @param students the students to prepare (those with runs to make)
     * @param work     the grading's work folder (each student's classes go to a folder of its own there)
     * @param stop     once set, no further submission is prepared
     * @param then     what is done with each submission once it is prepared
     */
    Compiling(List<Path> folders, Set<String> students, Path work, AtomicBoolean stop, Prepared then) {
        for (Path f : folders) {
            String student = f.getFileName().toString();
            if (students.contains(student)) {
                subs.put(student, CompletableFuture.supplyAsync(() -> {
                    if (stop.get()) {
                        return null;
                    }
                    Submission s = Submissions.prepare(f, work.resolve(student));
                    try {
                        then.prepared(s);
                    } catch (IOException e) {
                        throw new UncheckedIOException(e);
                    }
                    return s;
                }, thread));
            }
        }
    }

    /**
     * @param student a student of the grading with runs to make
     * @return the student's submission, prepared (waits for it), or null when the grading stopped before it was
     */
    Submission get(String student) {
        CompletableFuture<Submission> f = subs.get(student);
        if (f == null) {
            throw new IllegalArgumentException("no submission of " + student + " is prepared");
        }
        try {
            return f.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("grading was interrupted", e);
        } catch (ExecutionException | CompletionException e) {
            if (e.getCause() instanceof RuntimeException r) {
                throw r;
            }
            if (e.getCause() instanceof Error r) {
                throw r;
            }
            throw new IllegalStateException("a submission could not be prepared: " + e.getCause(), e.getCause());
        }
    }

    /** @param student a student of the grading @return true once the submission is prepared */
    boolean isDone(String student) {
        CompletableFuture<Submission> f = subs.get(student);
        return f != null && f.isDone();
    }

    /** Wait until every submission is prepared (and what is done with it, done). */
    void awaitAll() {
        for (String s : subs.keySet()) {
            get(s);
        }
    }

    /** Prepares no further submission. */
    @Override
    public void close() {
        thread.shutdownNow();
    }
}
