package org.kheperasim.testing;

/**
 * Everything a test about a run needs, as one static import:
 *
 * <pre>{@code
 * import static org.kheperasim.testing.KheperaAssertions.*;
 *
 * Run run = Run.of(MyController.class).in("maze").seconds(120).run();
 * assertThat(run).endedNormally().neverTouched(WALL).entered("c4_4").before(seconds(100));
 * }</pre>
 *
 * The assertions are plain JUnit 5: a failed one throws {@link org.opentest4j.AssertionFailedError}, which
 * every JUnit 5 test and build tool reports as a test failure.
 */
public final class KheperaAssertions {
    /** A wall of the arena, or its edge. */
    public static final Obstacle WALL = Obstacle.WALL;
    /** A lamp's body. */
    public static final Obstacle LAMP = Obstacle.LAMP;
    /** Another robot. */
    public static final Obstacle ROBOT = Obstacle.ROBOT;
    /** A bottle cap. */
    public static final Obstacle CAP = Obstacle.CAP;

    private KheperaAssertions() {
    }

    /**
     * @param run a run
     * @return assertions about every robot of the run
     */
    public static RunAssert assertThat(Run run) {
        return new RunAssert(run, run.robots());
    }

    /**
     * @param robot one robot of a run ({@code run.robot(1)})
     * @return assertions about that robot alone
     */
    public static RunAssert assertThat(RobotRun robot) {
        return new RunAssert(robot.run(), java.util.List.of(robot));
    }

    /**
     * @param seconds simulated seconds, 0 or more
     * @return that simulated time, e.g. {@code before(seconds(60))}
     */
    public static SimTime seconds(double seconds) {
        return SimTime.ofSeconds(seconds);
    }

    /**
     * @param millis simulated milliseconds, 0 or more
     * @return that simulated time
     */
    public static SimTime millis(long millis) {
        return SimTime.ofMillis(millis);
    }

    /**
     * @param minutes simulated minutes, 0 or more
     * @return that simulated time
     */
    public static SimTime minutes(double minutes) {
        return SimTime.ofSeconds(minutes * 60);
    }
}
