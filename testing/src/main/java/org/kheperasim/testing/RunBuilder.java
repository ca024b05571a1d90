package org.kheperasim.testing;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeMap;
import org.kheperasim.sim.testkit.KitArena;
import org.kheperasim.sim.testkit.KitSettings;
import org.kheperasim.sim.testkit.TestKit;

/**
 * Says what to run, then runs it: made by {@link Run#of(Class)} or {@link Run#of(String)}.
 *
 * <pre>{@code
 * Run run = Run.of(MyController.class).in("maze").seconds(120).seed(1).run();
 * }</pre>
 *
 * <p>Each method names one option of {@code khepera-sim run}, and a run made here is the run that command
 * makes with the same arena, controller, seed and settings, headless, with the trace it writes with
 * {@code --trace}: {@link Run#commandLine()} prints the command. Every robot start of the arena gets the
 * controller unless {@link #robot(int, Class)} gives one its own. The controller runs contained, as a
 * student's controller always does in the simulator (no files, no network: see the simulator's
 * docs/controller-rules.md), unless {@link #trusted()}.
 *
 * <p>A builder is not safe for use by several threads at once; {@link #run()} may be called again (each
 * call makes the same run again).
 */
public final class RunBuilder {
    private final ControllerClasses.Found controller;
    private final Map<Integer, ControllerClasses.Found> robotControllers = new TreeMap<>();
    private final Map<Integer, Map<String, String>> robotSettings = new TreeMap<>();
    private String arenaArg;
    private KitArena arena;
    private Double seconds;
    private long seed = 1;
    private KitSettings settings = KitSettings.defaults();
    private long sampleMillis = 50;
    private boolean trusted;
    private double hangTimeoutSeconds = RunSpec.DEFAULT_HANG_TIMEOUT;

    RunBuilder(ControllerClasses.Found controller) {
        this.controller = controller;
    }

    /**
     * @param arena a bundled arena's name ({@code lab}, {@code maze-easy}, {@code maze}, {@code maze-hard},
     *     {@code beacon-maze}, {@code two-rooms}) or the path of an arena file, relative to the project's folder
     *     (an existing file wins over a bundled name, as on the command line)
     * @return this
     * @throws IllegalArgumentException when it is neither
     * @throws RuntimeException naming the file and line when the file is not a valid arena
     */
    public RunBuilder in(String arena) {
        Objects.requireNonNull(arena, "arena");
        this.arena = TestKit.arena(arena);
        this.arenaArg = arena;
        return this;
    }

    /**
     * @param arenaFile an arena file ({@code .arena}, or a WSU Khepera Simulator world file)
     * @return this
     * @throws IllegalArgumentException when there is no such file
     */
    public RunBuilder in(Path arenaFile) {
        if (!Files.isRegularFile(arenaFile)) {
            throw new IllegalArgumentException("no arena file " + arenaFile.toAbsolutePath()
                    + "; give the path of an .arena"
                    + " file (relative to the project's folder), or a bundled arena's name with in(\"maze\")");
        }
        return in(arenaFile.toString());
    }

    /**
     * @param simulatedSeconds how long the run lasts, simulated seconds, more than 0 (default: the arena's
     *     {@code time-limit}, else 600 s, as {@code run}'s). A run ends earlier when every controller has ended.
     * @return this
     */
    public RunBuilder seconds(double simulatedSeconds) {
        if (!(simulatedSeconds > 0) || Double.isInfinite(simulatedSeconds)) {
            throw new IllegalArgumentException("seconds(" + simulatedSeconds
                    + "): give a positive number of simulated seconds");
        }
        this.seconds = simulatedSeconds;
        return this;
    }

    /**
     * @param duration how long the run lasts, simulated time (see {@link #seconds(double)})
     * @return this
     */
    public RunBuilder lasting(SimTime duration) {
        return seconds(duration.seconds());
    }

    /**
     * @param seed the run's seed: every noise of the run is drawn from it, so the same seed gives the same run
     *     (default 1, so a test repeats exactly; loop over seeds to test a controller against several)
     * @return this
     */
    public RunBuilder seed(long seed) {
        this.seed = seed;
        return this;
    }

    /**
     * Change a setting for every robot, as {@code --set key=value}; {@code java -jar khepera-sim.jar settings}
     * lists them (e.g. {@code noise.reading} 0 turns off the noise of every reading).
     *
     * @param key a setting's name
     * @param value its value
     * @return this
     * @throws IllegalArgumentException naming the setting and its allowed values when either is wrong
     */
    public RunBuilder set(String key, String value) {
        this.settings = settings.with(key, value);
        return this;
    }

    /**
     * Run the controller on the robot's own processor, as a program in its flash runs (and as swarms,
     * Enki and Webots run controllers): it reads the robot's latest 20 ms sensor scan and its
     * commands act at once, with no serial link between. The default for a {@code StepController};
     * the same as {@code set("controller.mode", "onboard")}.
     *
     * @return this
     */
    public RunBuilder onBoard() {
        return set("controller.mode", "onboard");
    }

    /**
     * Run the controller on the host, through the serial link model, as robot-link runs it on the
     * lab's robot: it sees the values of the poll cycle and its commands act after their wire time.
     * The default for a thread-style controller; the same as {@code set("controller.mode", "tethered")}.
     *
     * @return this
     */
    public RunBuilder tethered() {
        return set("controller.mode", "tethered");
    }

    /**
     * @param settingsFile a settings file ({@code key = value} lines, as the window saves them); settings
     *     given with {@link #set} before this are replaced, after it are added
     * @return this
     */
    public RunBuilder settings(Path settingsFile) {
        this.settings = KitSettings.load(settingsFile);
        return this;
    }

    /**
     * Give one robot of the arena its own controller, as {@code --robot N:controller=Name}.
     *
     * @param index the robot, 0 for the arena's first {@code robot} line
     * @param controllerClass its controller
     * @return this
     */
    public RunBuilder robot(int index, Class<?> controllerClass) {
        robotControllers.put(index, ControllerClasses.of(controllerClass));
        return this;
    }

    /**
     * @param index the robot, 0 for the arena's first {@code robot} line
     * @param controllerName its controller: a bundled controller's name or a class name on the test's classpath
     * @return this
     */
    public RunBuilder robot(int index, String controllerName) {
        robotControllers.put(index, ControllerClasses.named(controllerName));
        return this;
    }

    /**
     * Change a setting of one robot only, as {@code --robot N:key=value} (a worn motor, a dead sensor).
     *
     * @param index the robot, 0 for the arena's first {@code robot} line
     * @param key a per-robot setting's name
     * @param value its value
     * @return this
     */
    public RunBuilder robotSetting(int index, String key, String value) {
        if (KitSettings.wholeRun(key)) {
            throw new IllegalArgumentException("robotSetting(" + index + ", \"" + key + "\", ...): " + key
                    + " is one setting"
                    + " for the whole run, not per robot; give it with set(\"" + key + "\", \"" + value + "\")");
        }
        KitSettings.defaults().with(key, value);
        robotSettings.computeIfAbsent(index, i -> new LinkedHashMap<>()).put(key, value);
        return this;
    }

    /**
     * @param period how often the run is sampled: the path's points, the contacts seen, the trace's lines,
     *     whole milliseconds, 1 ms to 1 hour (default 50 ms, as {@code run --trace}'s; 1 ms sees every tick but
     *     makes a trace of some 150 bytes per robot per millisecond)
     * @return this
     */
    public RunBuilder sampleEvery(SimTime period) {
        long ms = period.millis();
        if (period.nanos() % 1_000_000L != 0 || ms < 1 || ms > 3_600_000) {
            throw new IllegalArgumentException("sampleEvery(" + period
                    + "): give whole milliseconds from 1 ms to 1 hour,"
                    + " e.g. sampleEvery(millis(10))");
        }
        this.sampleMillis = ms;
        return this;
    }

    /**
     * Run the controllers uncontained, as {@code --trusted}: files, the network and reflection are allowed. Only for
     * code you trust (your own); a course grading students' controllers never uses it.
     *
     * @return this
     */
    public RunBuilder trusted() {
        this.trusted = true;
        return this;
    }

    /**
     * @param realSeconds real (wall-clock) seconds a controller may go without an API call before it counts as
     *     hung, more than 0 (default 5, as {@code run}'s)
     * @return this
     */
    public RunBuilder hangTimeout(double realSeconds) {
        if (!(realSeconds > 0) || Double.isInfinite(realSeconds)) {
            throw new IllegalArgumentException("hangTimeout(" + realSeconds
                    + "): give a positive number of real seconds");
        }
        this.hangTimeoutSeconds = realSeconds;
        return this;
    }

    /**
     * Run it, headless, and wait for the end: usually far faster than real time.
     *
     * @return what happened
     * @throws IllegalStateException when no arena was given
     * @throws IllegalArgumentException when a robot index is not one of the arena's robots
     * @throws org.opentest4j.AssertionFailedError when a controller cannot run at all (refused for a forbidden
     *     call, or its constructor threw), naming it and the student's line
     */
    public Run run() {
        Run run = LiveRuns.run(spec());
        TestRuns.made(run);
        return run;
    }

    RunSpec spec() {
        if (arena == null) {
            throw new IllegalStateException(
                    "no arena: say where to run, e.g. .in(\"lab\") or .in(Path.of(\"src/test/resources/my.arena\"))");
        }
        int n = arena.robotCount();
        Set<Integer> given = new LinkedHashSet<>(robotControllers.keySet());
        given.addAll(robotSettings.keySet());
        for (int i : given) {
            if (i < 0 || i >= n) {
                throw new IllegalArgumentException("robot " + i + " was given a controller or setting, but the arena "
                        + arena.name() + " has robots 0.." + (n - 1));
            }
        }
        List<String> names = new ArrayList<>();
        List<KitSettings> each = new ArrayList<>();
        Set<Path> classpath = new LinkedHashSet<>();
        for (int i = 0; i < n; i++) {
            ControllerClasses.Found c = robotControllers.getOrDefault(i, controller);
            names.add(c.name());
            c.root().ifPresent(classpath::add);
            KitSettings s = settings;
            for (Map.Entry<String, String> e : robotSettings.getOrDefault(i, Map.of()).entrySet()) {
                s = s.with(e.getKey(), e.getValue());
            }
            each.add(s);
        }
        double s = seconds != null ? seconds : arena.timeLimitOr(600);
        return new RunSpec(arenaArg, arena, names, each, new ArrayList<>(classpath), seed, s, sampleMillis, trusted,
                hangTimeoutSeconds, null);
    }
}
