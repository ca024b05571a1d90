package org.kheperasim.sim.eval;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.host.HostOptions;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;

/**
 * Evaluates many jobs ({@link Job}: a controller with parameters, an arena, a seed, a simulated
 * time) on the cores of one machine, in one warm JVM: each on a thread of a fixed pool, each a run of
 * its own, headless. A job's outcome depends on the job alone, so the outcomes are the same for any
 * number of threads and in any order of completion. Arenas are read once; a stateless controller's
 * classes are defined once for all jobs (the JIT settles on them).
 *
 * <p>The controllers run as the user's own code ({@code trusted}): an evaluation is of one's own
 * controllers, for an evolutionary algorithm or a parameter sweep. Code that is not one's own is
 * graded, in the sandbox ({@code khepera-sim grade}).
 */
public final class Evaluator implements AutoCloseable {
    private final List<Path> classpath;
    private final boolean trusted;
    private final ExecutorService pool;
    private final Map<String, Arena> arenas = new ConcurrentHashMap<>();

    /** The engine keeps to one thread per job when jobs run on several threads. */
    private final HostOptions hostOptions;
    /** The robot for the arenas' robot lines that name none ({@code --robot-file}), or null: theirs. */
    private volatile org.kheperasim.sim.arena.RobotKind robot;

    /**
     * @param kind the robot for every arena's robot lines that name none, or null: the Khepera I
     * @return this evaluator
     */
    public Evaluator robot(org.kheperasim.sim.arena.RobotKind kind) {
        this.robot = kind;
        return this;
    }

    /**
     * @param classpath folders and jars with the controllers' classes
     * @param trusted run the controllers unchecked (the user's own code), or checked against the allowlist
     * @param threads jobs at once, at least 1 (the machine's cores, say)
     */
    public Evaluator(List<Path> classpath, boolean trusted, int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException("--threads " + threads + ": give at least 1");
        }
        this.classpath = List.copyOf(classpath);
        this.trusted = trusted;
        AtomicInteger n = new AtomicInteger();
        ThreadFactory named = r -> {
            // Inheriting no thread-local values from the caller.
            Thread t = new Thread(null, r, "khepera-evaluate-" + n.incrementAndGet(), 0, false);
            t.setDaemon(true);
            return t;
        };
        this.pool = Executors.newFixedThreadPool(threads, named);
        // Jobs on every core already: a swarm's step keeps to its job's thread (the same outcome either way).
        this.hostOptions = threads > 1 ? HostOptions.defaults().withEngineThreads(1) : HostOptions.defaults();
    }

    /**
     * Evaluate a job on the pool; {@code done} is told its outcome on the pool's thread, when it ends.
     *
     * @param job the job
     * @param done told the outcome
     * @return the job's future outcome
     */
    public Future<Outcome> submit(Job job, Consumer<Outcome> done) {
        return pool.submit(() -> {
            Outcome o = evaluate(job);
            done.accept(o);
            return o;
        });
    }

    /**
     * @param jobs jobs
     * @return their outcomes, in the jobs' order (evaluated on the pool)
     * @throws InterruptedException if interrupted while waiting
     */
    public List<Outcome> evaluateAll(List<Job> jobs) throws InterruptedException {
        List<Future<Outcome>> futures = new ArrayList<>();
        for (Job j : jobs) {
            futures.add(submit(j, o -> { }));
        }
        List<Outcome> out = new ArrayList<>();
        for (Future<Outcome> f : futures) {
            try {
                out.add(f.get());
            } catch (java.util.concurrent.ExecutionException e) {
                throw new IllegalStateException("evaluating a job failed: " + e.getCause(), e.getCause());
            }
        }
        return out;
    }

    /**
     * Evaluate one job on the calling thread.
     *
     * @param job the job
     * @return its outcome
     */
    public Outcome evaluate(Job job) {
        Arena arena;
        Settings settings;
        try {
            arena = arenas.computeIfAbsent(job.arena(), ArenaFormat::resolve);
            if (robot != null) {
                arena = arena.withDefaultRobot(robot);
            }
            settings = Settings.defaults();
            for (Map.Entry<String, String> e : new java.util.TreeMap<>(job.settings()).entrySet()) {
                settings = settings.with(e.getKey(), e.getValue());
            }
        } catch (RuntimeException e) {
            return new Outcome(job, null, null, message(e));
        }
        try {
            Simulation.Builder run = Simulation.builder().arena(arena).classpath(classpath).trusted(trusted)
                    .controller(job.controller()).seed(job.seed()).seconds(job.seconds()).settings(settings)
                    .parameters(job.parameters()).hostOptions(hostOptions);
            if (job.trace() != null) {
                run.trace(job.trace());
            }
            RunResult result = run.run();
            Score score = arena.assignment().hasTasks() ? Score.of(arena, RunFacts.of(result)) : null;
            return new Outcome(job, result, score, null);
        } catch (RuntimeException e) {
            return new Outcome(job, null, null, message(e));
        }
    }

    private static String message(RuntimeException e) {
        String m = e.getMessage();
        return m == null ? e.toString() : m;
    }

    /** Finish the jobs submitted, and stop the pool. */
    @Override
    public void close() {
        pool.shutdown();
        try {
            while (!pool.awaitTermination(1, TimeUnit.SECONDS)) {
                Thread.onSpinWait();
            }
        } catch (InterruptedException e) {
            pool.shutdownNow();
            Thread.currentThread().interrupt();
        }
    }
}
