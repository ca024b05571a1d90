package org.kheperasim.testing;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.kheperasim.sim.testkit.KitRegion;
import org.kheperasim.sim.testkit.KitTraceDiff;
import org.kheperasim.sim.testkit.TestKit;

/**
 * A run of the simulator, shaped for a test's assertions: each robot's path, contacts, regions entered
 * and how its controller ended, the caps, the score of the arena's tasks, and the trace.
 *
 * <p>Made by running a controller, headless:
 * <pre>{@code
 * Run run = Run.of(MyController.class).in("maze").seconds(120).seed(1).run();
 * assertThat(run).endedNormally().neverTouched(WALL).entered("c4_4").before(seconds(100));
 * }</pre>
 * or by reading a recorded run, a trace written by {@code khepera-sim run --trace FILE} or a run recording
 * folder saved from the window:
 * <pre>{@code
 * Run recorded = Run.load(Path.of("src/test/resources/lap.trace"));
 * assertThat(recorded).entered("goal").before(seconds(60));
 * assertThat(recorded).replaysIdentically();
 * }</pre>
 * A recorded run has the same shape, less what a trace does not record: how the controllers ended, the
 * engine's contact events (its contacts are those its samples saw), the collision count and the floor
 * covered. Regions are checked at every sample of a trace, where a run made here has the simulator's millisecond times.
 *
 * <p>Immutable, apart from remembering where its trace was saved.
 */
public final class Run {
    private final RunSpec spec;
    private final Path recordedFrom;
    private final SimTime duration;
    private final List<RobotRun> robots;
    private final List<Cap> caps;
    private final Score score;
    private final String trace;
    private final List<String> console;
    private Path saved;

    Run(RunSpec spec, Path recordedFrom, SimTime duration, List<RobotRun> robots, List<Cap> caps, Score score,
            String trace, List<String> console) {
        this.spec = spec;
        this.recordedFrom = recordedFrom;
        this.duration = duration;
        this.robots = List.copyOf(robots);
        this.robots.forEach(r -> r.partOf(this));
        this.caps = List.copyOf(caps);
        this.score = score;
        this.trace = trace;
        this.console = List.copyOf(console);
    }

    /**
     * Start saying what to run: a controller class of the test's project (or a bundled one).
     *
     * @param controller the controller's class, e.g. {@code MyController.class}: a {@code Controller} or
     *     {@code StepController} subclass, or an Appendix-style {@code Thread} with a
     *     {@code (CurrentRobotState, MessagePasser)} constructor
     * @return the builder: give at least the arena with {@link RunBuilder#in(String)}, then {@link RunBuilder#run()}
     */
    public static RunBuilder of(Class<?> controller) {
        return new RunBuilder(ControllerClasses.of(controller));
    }

    /**
     * @param controller a bundled controller's name ({@code WallFollower}, {@code Braitenberg}, ...) or the name of
     *     a controller class on the test's classpath ({@code mypackage.MyController})
     * @return the builder (see {@link #of(Class)})
     * @throws IllegalArgumentException when there is no such controller
     */
    public static RunBuilder of(String controller) {
        return new RunBuilder(ControllerClasses.named(controller));
    }

    /**
     * Read a recorded run: a trace file ({@code khepera-sim run --trace FILE}, or one a test saved) or a run
     * recording folder saved from the window. Its arena is found as {@code khepera-sim verify} finds it: the
     * recording's {@code start.arena}, an arena file of the recorded name beside the trace, or the bundled arena
     * of that name, whichever has the SHA-256 the trace records.
     *
     * @param recording the trace file or recording folder
     * @return the run as recorded
     * @throws IllegalArgumentException when the file is missing or its arena cannot be found
     * @throws RuntimeException naming the file and line when the trace is damaged
     */
    public static Run load(Path recording) {
        return RecordedRuns.load(recording, null);
    }

    /**
     * @param trace a trace file
     * @param arenaFile the arena file it was recorded in
     * @return the run as recorded (see {@link #load(Path)})
     */
    public static Run load(Path trace, Path arenaFile) {
        return RecordedRuns.load(trace, arenaFile);
    }

    /** @return the arena's name */
    public String arena() {
        return spec.arena().name();
    }

    /** @return the run's seed */
    public long seed() {
        return spec.seed();
    }

    /**
     * @return the settings every robot had, as a trace's header states them: {@code defaults} or {@code key=value ...}
     */
    public String settings() {
        return spec.settings().get(0).describe();
    }

    /** @return the simulated time the run lasted (shorter than asked when every controller ended before) */
    public SimTime duration() {
        return duration;
    }

    /** @return every robot, in the arena's order */
    public List<RobotRun> robots() {
        return robots;
    }

    /** @return robot 0: the only robot of a one-robot arena */
    public RobotRun robot() {
        return robots.get(0);
    }

    /**
     * @param index a robot's index, 0 for the arena's first {@code robot} line
     * @return that robot
     * @throws IllegalArgumentException when the run has no such robot
     */
    public RobotRun robot(int index) {
        if (index < 0 || index >= robots.size()) {
            throw new IllegalArgumentException("robot " + index + ": the run has robots 0.." + (robots.size() - 1));
        }
        return robots.get(index);
    }

    /** @return the arena's caps, in the order of its {@code cap} lines (empty when it has none) */
    public List<Cap> caps() {
        return caps;
    }

    /**
     * @param region a region's name, as in the arena file
     * @return how many caps lie on the floor inside it at the end (what a {@code task deliver} counts)
     * @throws IllegalArgumentException when the arena has no such region
     */
    public int capsIn(String region) {
        KitRegion r = region(region);
        return (int) caps.stream().filter(c -> c.heldAtEnd() < 0 && r.contains(c.endX(), c.endY())).count();
    }

    /**
     * @return the score of the arena's tasks, as {@code khepera-sim run} prints it (0/0 when the arena sets no task)
     */
    public Score score() {
        return score;
    }

    /**
     * @return the run's trace, as {@code khepera-sim run --trace FILE} writes it (for a recorded run, the file's text)
     */
    public String trace() {
        return trace;
    }

    /**
     * @return the controllers' messages and the simulator's errors, each as {@code khepera-sim run} prints it
     *     ({@code [  12.345 s] MyController: text}); empty for a recorded run
     */
    public List<String> console() {
        return console;
    }

    /** @return the trace file or recording folder the run was read from; empty for a run made by a test */
    public Optional<Path> recordedFrom() {
        return Optional.ofNullable(recordedFrom);
    }

    /**
     * @return the {@code khepera-sim run} command that makes this run (for a recorded run: the run that
     *     {@link #rerun()} makes, less a window recording's arena edits)
     */
    public String commandLine() {
        return spec.commandLine();
    }

    /**
     * Save the trace in a folder, with the arena beside it so that the window (File &gt; Open recording) and
     * {@code khepera-sim verify} find it. A failing assertion does this itself (see {@link RunReports}).
     *
     * @param folder where to write: {@code NAME.trace}, {@code ARENA.arena} and {@code NAME.txt} (the command
     *     that makes the run, and its console)
     * @return the trace file
     * @throws java.io.UncheckedIOException naming the folder when it cannot be written
     */
    public Path saveTo(Path folder) {
        return RunFiles.save(this, folder);
    }

    /** @return where the trace was last saved ({@link #saveTo}, a failing assertion, {@link RunReports}), if it was */
    public synchronized Optional<Path> savedTrace() {
        return Optional.ofNullable(saved);
    }

    synchronized void saved(Path trace) {
        this.saved = trace;
    }

    /**
     * Make the run again, from the same arena, controllers, seed and settings, and compare the traces: the
     * simulator is deterministic, so they are identical unless the controller is not (it reads something
     * the simulator does not control) or, for a recorded run, the controller, the arena or the simulator
     * changed since. A recorded run's controllers are looked up on the test's classpath.
     *
     * @return whether it came out identical, and if not, where it first differs
     */
    public Rerun rerun() {
        RunSpec again = recordedFrom == null ? spec : Rerun.withClasspath(spec);
        Run made = LiveRuns.run(again);
        KitTraceDiff diff = TestKit.compareTraces(trace, made.trace);
        return new Rerun(made, diff.header(), Optional.ofNullable(diff.firstSample()), diff.samples());
    }

    RunSpec spec() {
        return spec;
    }

    /** @return the arena's region of this name */
    KitRegion region(String name) {
        for (KitRegion r : spec.arena().regions()) {
            if (r.name().equals(name)) {
                return r;
            }
        }
        throw new IllegalArgumentException("the arena " + arena() + " has no region named '" + name
                + "'; its regions are "
                + (spec.arena().regions().isEmpty() ? "none" : String.join(", ",
                spec.arena().regions().stream().map(KitRegion::name).toList())));
    }

    /**
     * @return e.g. {@code MyController in lab, seed 1, 60.000 s: ended at (380.0, 610.2) mm heading 90.0 deg; score
     *     0/100}
     */
    @Override
    public String toString() {
        StringBuilder s = new StringBuilder(robots.size() == 1 ? robot().name() : robots.size() + " robots")
                .append(" in ").append(arena()).append(", seed ").append(seed()).append(", ").append(duration);
        if (robots.size() == 1) {
            s.append(": ended at ").append(robot().finalPose());
        }
        if (score.max() > 0) {
            s.append("; score ").append(score);
        }
        return s.toString();
    }
}
