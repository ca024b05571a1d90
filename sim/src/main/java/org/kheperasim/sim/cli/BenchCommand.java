package org.kheperasim.sim.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code bench}: how fast the engine runs a controller, in simulated seconds per wall second. The
 * default scenario is the spine's benchmark: one robot running Braitenberg (a 100 ms control
 * period) in the lab for 600 simulated seconds.
 */
@Command(name = "bench", mixinStandardHelpOptions = true, sortOptions = false,
        description = "Measure simulated seconds per wall second (one warm-up run, then the measured runs).")
final class BenchCommand implements Callable<Integer> {

    @Option(names = "--arena", defaultValue = "lab", description = "arena (default: ${DEFAULT-VALUE})")
    String arena;

    @Option(names = "--controller", defaultValue = "Braitenberg", description = "controller (default: ${DEFAULT-VALUE})")
    String controller;

    @Option(names = "--seconds", defaultValue = "600", description = "simulated seconds per run (default: ${DEFAULT-VALUE})")
    double seconds;

    @Option(names = "--runs", defaultValue = "5", description = "measured runs (default: ${DEFAULT-VALUE})")
    int runs;

    @Option(names = "--seed", defaultValue = "1", description = "seed of the first run; each run adds one (default: ${DEFAULT-VALUE})")
    long seed;

    @Override
    public Integer call() {
        System.out.printf(Locale.ROOT, "benchmark: %s in %s, %.0f simulated s per run, %d runs after a warm-up, %d cores, %s%n",
                controller, arena, seconds, runs, Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.name") + " " + System.getProperty("java.version"));
        run(seed - 1);
        List<Double> factors = new ArrayList<>();
        for (int i = 0; i < runs; i++) {
            RunResult r = run(seed + i);
            factors.add(r.realTimeFactor());
            System.out.printf(Locale.ROOT, "run %d: seed %d, %.1f s simulated in %.3f s wall = %,.0f x real time%n",
                    i + 1, r.seed(), r.simulatedSeconds(), r.wallSeconds(), r.realTimeFactor());
        }
        List<Double> sorted = new ArrayList<>(factors);
        sorted.sort(null);
        System.out.printf(Locale.ROOT, "median: %,.0f simulated seconds per wall second (min %,.0f, max %,.0f)%n",
                sorted.get(sorted.size() / 2), sorted.get(0), sorted.get(sorted.size() - 1));
        return 0;
    }

    private RunResult run(long runSeed) {
        return Simulation.builder().arena(arena).controller(controller).seconds(seconds).seed(runSeed).run();
    }
}
