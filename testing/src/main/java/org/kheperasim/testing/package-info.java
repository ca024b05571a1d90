/**
 * Testing Khepera controllers with JUnit 5: run a controller in the simulator from a test, headless and
 * deterministic, and assert on what the robot did. Everything a test needs is in this package.
 *
 * <pre>{@code
 * import static org.kheperasim.testing.KheperaAssertions.*;
 *
 * import org.junit.jupiter.api.Test;
 * import org.junit.jupiter.api.extension.ExtendWith;
 * import org.kheperasim.testing.*;
 *
 * @ExtendWith(RunReports.class)
 * class MyControllerTest {
 *     @Test
 *     void reachesTheGoalWithoutTouchingAWall() {
 *         Run run = Run.of(MyController.class).in("beacon-maze").seconds(300).seed(1).run();
 *         assertThat(run).endedNormally().neverTouched(WALL).entered("goal").before(seconds(240));
 *     }
 * }
 * }</pre>
 *
 * <ul>
 *   <li>{@link org.kheperasim.testing.Run#of(Class)} and {@link org.kheperasim.testing.RunBuilder} make a run:
 *       the controller, the arena (a bundled one or a file), the simulated duration, the seed and the settings,
 *       for one robot or each robot of the arena. The run is the one {@code khepera-sim run} makes with the
 *       same options, with the trace {@code --trace} writes.</li>
 *   <li>{@link org.kheperasim.testing.Run} is what happened: per robot ({@link org.kheperasim.testing.RobotRun})
 *       the final pose, the sampled path, the contacts with what and when, the regions entered and when, how the
 *       controller ended ({@link org.kheperasim.testing.Ending}, with the student's file and line when it threw or
 *       broke a rule); the caps; the score of the arena's tasks; the trace.
 *       {@link org.kheperasim.testing.Run#load(java.nio.file.Path)} reads a recorded run into the same shape, and
 *       {@link org.kheperasim.testing.Run#rerun()} makes any run again and says whether it is identical.</li>
 *   <li>{@link org.kheperasim.testing.KheperaAssertions} holds the assertions; a failure says what was expected,
 *       what happened, at what simulated time, and where the run's trace was saved.</li>
 *   <li>{@link org.kheperasim.testing.RunReports} keeps the runs of every failing test.</li>
 * </ul>
 *
 * <p>Units: millimetres from the arena's lower-left corner (x right, y up), headings in degrees
 * counter-clockwise from +x, times in simulated time ({@link org.kheperasim.testing.SimTime}), never the wall clock.
 */
package org.kheperasim.testing;
