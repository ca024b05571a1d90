package org.kheperasim.sim.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kheperasim.link.tool.BundledControllers;
import org.kheperasim.link.tool.CliNumbers;
import org.kheperasim.link.tool.ExitCodes;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.host.ConsoleLine;
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
        description = "Measure simulated seconds per wall second (warm-up runs, then the measured runs).")
final class BenchCommand implements Callable<Integer> {

    @Option(names = "--arena", defaultValue = "lab", completionCandidates = BundledArenas.class,
            description = "an arena file, or a bundled arena (${COMPLETION-CANDIDATES}) (default: ${DEFAULT-VALUE})")
    String arena;

    @Option(names = "--controller", defaultValue = "Braitenberg", completionCandidates = BundledControllers.class,
            description = "a bundled controller (${COMPLETION-CANDIDATES}) or a class name (default: ${DEFAULT-VALUE})")
    String controller;

    @Option(names = "--classpath", paramLabel = "PATHS", split = "${sys:path.separator}",
            description = "folders and jars with compiled controllers (for your own --controller)")
    List<java.nio.file.Path> classpath = new ArrayList<>();

    @Option(names = "--seconds", defaultValue = "600", converter = CliNumbers.PositiveSeconds.class,
            description = "simulated seconds per run (default: ${DEFAULT-VALUE})")
    double seconds;

    @Option(names = "--runs", defaultValue = "5", converter = CliNumbers.PositiveInt.class,
            description = "measured runs (default: ${DEFAULT-VALUE})")
    int runs;

    @Option(names = "--warm-up", defaultValue = "2", paramLabel = "SECONDS",
            converter = CliNumbers.NonNegativeDecimal.class,
            description = "before measuring, run for at least this much wall time (one run at least), so that the JIT"
                    + " has compiled what the runs use (default: ${DEFAULT-VALUE})")
    double warmUp;

    @Option(names = "--seed", defaultValue = "1", converter = CliNumbers.AnyLong.class,
            description = "seed of the first run; each run adds one (default: ${DEFAULT-VALUE})")
    long seed;

    @Option(names = "--add-caps", defaultValue = "0", paramLabel = "N", converter = CliNumbers.NonNegativeInt.class,
            description = "scatter N more caps over the arena's free floor, on an even lattice (default:"
                    + " ${DEFAULT-VALUE})")
    int addCaps;

    @Option(names = "--robots", defaultValue = "0", paramLabel = "N", converter = CliNumbers.NonNegativeInt.class,
            description = "instead of --arena: a walled square made for N robots, one per 200 mm cell, all running the"
                    + " controller (default: the arena's own robots)")
    int robots;

    @Option(names = "--engine-threads", paramLabel = "N", converter = CliNumbers.PositiveInt.class,
            description = "threads the world's step may use for a swarm of 64 robots or more: 1 or 2 (default: 2 on a"
                    + " machine with two cores or more); a run is the same either way")
    Integer engineThreads;

    @picocli.CommandLine.Mixin
    SettingsOptions settingsOptions = new SettingsOptions();

    private org.kheperasim.sim.host.HostOptions hostOptions;

    private Arena scenario;
    private org.kheperasim.sim.engine.model.Settings settings;
    /** Where the first run's controllers ran ({@code RunSession.modeLine}), printed with the figures. */
    private volatile String modeLine;

    @Override
    public Integer call() {
        if (robots > org.kheperasim.sim.arena.ArenaLimits.MAX_ROBOTS) {
            throw new IllegalArgumentException("--robots " + robots + ": at most "
                    + org.kheperasim.sim.arena.ArenaLimits.MAX_ROBOTS + " robots");
        }
        settings = settingsOptions.settings();
        hostOptions = engineThreads == null ? org.kheperasim.sim.host.HostOptions.defaults()
                : org.kheperasim.sim.host.HostOptions.defaults().withEngineThreads(engineThreads);
        scenario = withCaps(robots > 0 ? Swarm.arena(robots) : ArenaFormat.resolve(arena), addCaps);
        if (robots > 0) {
            arena = scenario.name();
        }
        System.out.printf(Locale.ROOT,
                "benchmark: %s in %s with %d caps, %.0f simulated s per run, %d runs after a warm-up,"
                + " %d cores, %s%n", controller, arena, scenario.caps().size(), seconds, runs,
                Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.name") + " " + System.getProperty("java.version"));
        long warmStart = System.nanoTime();
        int warmRuns = 0;
        do {
            RunResult r = run(seed - 1);
            if (warmRuns == 0 && failed(r)) {
                return ExitCodes.FAILED;
            }
            warmRuns++;
        } while (System.nanoTime() - warmStart < warmUp * 1e9);
        System.out.printf(Locale.ROOT, "warm-up: %d run%s in %.1f s of wall time%n", warmRuns, warmRuns == 1 ? "" : "s",
                (System.nanoTime() - warmStart) / 1e9);
        System.out.println(modeLine + (settings.overrides().isEmpty() ? "" : "; settings " + settings.describe())
                + (scenario.robots().size() >= 64 ? "; world step on " + hostOptions.engineThreads() + " thread"
                        + (hostOptions.engineThreads() == 1 ? "" : "s") : ""));
        List<Double> factors = new ArrayList<>();
        List<Double> cpuPerRobotSecond = new ArrayList<>();
        for (int i = 0; i < runs; i++) {
            long cpu0 = processCpuNanos();
            RunResult r = run(seed + i);
            long cpu = processCpuNanos() - cpu0;
            factors.add(r.realTimeFactor());
            double robotSeconds = r.simulatedSeconds() * r.robots().size();
            String cpuText = "";
            if (cpu0 >= 0 && robotSeconds > 0) {
                cpuPerRobotSecond.add(cpu / 1e3 / robotSeconds);
                cpuText = String.format(Locale.ROOT, "; process CPU %.3f s = %.1f us per robot-second", cpu / 1e9,
                        cpu / 1e3 / robotSeconds);
            }
            System.out.printf(Locale.ROOT, "run %d: seed %d, %.1f s simulated in %.3f s wall = %,.0f x real time%s%n",
                    i + 1, r.seed(), r.simulatedSeconds(), r.wallSeconds(), r.realTimeFactor(), cpuText);
        }
        List<Double> sorted = new ArrayList<>(factors);
        sorted.sort(null);
        System.out.printf(Locale.ROOT, "median: %,.0f simulated seconds per wall second (min %,.0f, max %,.0f)%n",
                sorted.get(sorted.size() / 2), sorted.get(0), sorted.get(sorted.size() - 1));
        if (!cpuPerRobotSecond.isEmpty()) {
            cpuPerRobotSecond.sort(null);
            System.out.printf(Locale.ROOT, "median CPU: %.1f us per robot-second (min %.1f, max %.1f), the whole"
                    + " process's (the JIT's and collector's threads included)%n",
                    cpuPerRobotSecond.get(cpuPerRobotSecond.size() / 2), cpuPerRobotSecond.get(0),
                    cpuPerRobotSecond.get(cpuPerRobotSecond.size() - 1));
        }
        System.out.println(load());
        Swarm.printSetUpAndMemory(() -> run(seed + runs, 0.001),
                whileRunning -> Simulation.builder().arena(scenario).controller(controller)
                        .classpath(classpath).seconds(0.001)
                        .settings(settings)
                        .seed(seed + runs)
                        .listener(s -> whileRunning.run(), 1).run());
        return 0;
    }

    /** @return the CPU time this process has used, all its threads, ns; -1 when the JVM does not say */
    private static long processCpuNanos() {
        return java.lang.management.ManagementFactory.getOperatingSystemMXBean()
                instanceof com.sun.management.OperatingSystemMXBean os ? os.getProcessCpuTime() : -1;
    }

    /**
     * The machine's load as the operating system reports it (the runs themselves count in it): a
     * figure is only comparable with one taken under a similar load.
     */
    private static String load() {
        double load = java.lang.management.ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
        return load < 0 ? "machine load: not reported by this system"
                : String.format(Locale.ROOT, "machine load: %.2f (1-minute average, these runs included) on %d cores",
                        load, Runtime.getRuntime().availableProcessors());
    }

    private RunResult run(long runSeed) {
        return run(runSeed, seconds);
    }

    private RunResult run(long runSeed, double runSeconds) {
        return Simulation.builder().arena(scenario).controller(controller).classpath(classpath).seconds(runSeconds)
                .settings(settings).hostOptions(hostOptions).onStart(session -> {
                    if (modeLine == null) {
                        modeLine = session.modeLine();
                    }
                })
                .seed(runSeed).console(line -> {
                    if (collecting && line.kind() == ConsoleLine.Kind.ERROR && errors.size() < 5) {
                        errors.add(line.format());
                    }
                }).run();
    }

    /** The first errors of the first run (the benchmark prints them when it fails); nothing is kept from the others. */
    private final List<String> errors = new java.util.concurrent.CopyOnWriteArrayList<>();
    private volatile boolean collecting = true;

    /**
     * @return true (and says so) when a robot's controller failed in the first run: its figures would measure nothing
     */
    private boolean failed(RunResult r) {
        for (int i = 0; i < r.robots().size(); i++) {
            RunResult.RobotResult robot = r.robots().get(i);
            if (robot.status().failed()) {
                errors.forEach(System.err::println);
                System.err.println("khepera-sim: error: robot " + i + "'s controller (" + robot.name() + ") ended "
                        + robot.status().name().toLowerCase(Locale.ROOT) + " in the first run; a benchmark of a failing"
                        + " controller measures nothing: fix it, or try it with 'run' first");
                return true;
            }
        }
        collecting = false;
        errors.clear();
        return false;
    }

    /**
     * The arena with {@code n} more caps on the floor: lattice points over the whole arena, kept
     * where a cap is clear of walls, lights, other caps and the robots' start poses, taken in an
     * order that spreads them out.
     */
    static Arena withCaps(Arena arena, int n) {
        if (n <= 0) {
            return arena;
        }
        DistanceField field = DistanceField.of(OccupancyGrid.of(arena));
        List<Cap> caps = new ArrayList<>(arena.caps());
        int side = 2;
        while (true) {
            List<Cap> found = new ArrayList<>();
            for (int i = 0; i < side && found.size() < n; i++) {
                for (int j = 0; j < side && found.size() < n; j++) {
                    double x = arena.width() * (i + 0.5) / side;
                    double y = arena.height() * (j + 0.5) / side;
                    if (clear(arena, field, caps, found, x, y)) {
                        found.add(new Cap(x, y));
                    }
                }
            }
            if (found.size() == n) {
                caps.addAll(found);
                return new Arena(arena.name(), arena.width(), arena.height(), arena.robots(), arena.walls(),
                        arena.lights(), caps, arena.regions());
            }
            if (side > 200) {
                throw new IllegalArgumentException("no room for " + n + " more caps in " + arena.name());
            }
            side++;
        }
    }

    private static boolean clear(Arena arena, DistanceField field, List<Cap> a, List<Cap> b, double x, double y) {
        if (field.preciseClearance(x, y) < 3 * Cap.DEFAULT_RADIUS) {
            return false;
        }
        for (Pose p : arena.robots()) {
            if (StrictMath.hypot(p.x() - x, p.y() - y) < 80) {
                return false;
            }
        }
        for (List<Cap> list : List.of(a, b)) {
            for (Cap c : list) {
                if (StrictMath.hypot(c.x() - x, c.y() - y) < 4 * Cap.DEFAULT_RADIUS) {
                    return false;
                }
            }
        }
        return true;
    }
}
