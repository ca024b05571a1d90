package org.kheperasim.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.testing.KheperaAssertions.CAP;
import static org.kheperasim.testing.KheperaAssertions.LAMP;
import static org.kheperasim.testing.KheperaAssertions.ROBOT;
import static org.kheperasim.testing.KheperaAssertions.WALL;
import static org.kheperasim.testing.KheperaAssertions.assertThat;
import static org.kheperasim.testing.KheperaAssertions.seconds;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.opentest4j.AssertionFailedError;

/**
 * The assertions pass when the run did what they say, and otherwise fail with a message a student can act
 * on: what was expected, what happened and at what simulated time, which run, and the trace, saved where
 * the message says, with its arena beside it.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class AssertionMessagesTest {
    private static Run intoTheWall;
    private static Run headOn;

    @BeforeAll
    static void runs() {
        intoTheWall = Run.of(student.Straight.class).in("lab").seconds(30).seed(3).set("noise.robot", "0").run();
        headOn = Run.of(student.Straight.class).in(Fixtures.resource("head-on.arena")).seconds(20).run();
    }

    @Test
    void aPassingChainReadsAsTheTestSays() {
        assertThat(intoTheWall).endedNormally().entered("upper_right").before(seconds(1)).neverTouched(ROBOT, LAMP, CAP)
                .endedIn("upper_right").endedNear(609.6, 1183.7, 5).travelledAtLeast(500);
        assertThat(headOn.robot(1)).neverEntered("left_end").neverTouched(WALL, CAP);
        assertThat(headOn).delivered(1, "left_end").entered("middle").before(seconds(0.001));
    }

    @Test
    void touchingAWallNamesTheTimeTheSideAndTheTrace() throws Exception {
        AssertionFailedError e = assertThrows(AssertionFailedError.class, () -> assertThat(intoTheWall).neverTouched(WALL));
        String m = e.getMessage();
        assertTrue(m.startsWith("Straight touched a wall at 14."), m);
        assertTrue(m.contains("\n  expected: never to touch a wall\n"), m);
        assertTrue(m.contains("\n  happened: touched a wall from 14."), m);
        assertTrue(Pattern.compile("\\(front side, robot at \\(6\\d\\d\\.\\d, 118\\d\\.\\d\\) mm\\)").matcher(m).find(), m);
        assertTrue(m.contains("\n  run:      Straight in lab, seed 3, settings noise.robot=0, 30.000 s simulated\n"), m);
        Path trace = tracePath(m);
        assertEquals(Path.of("target/kheperasim-runs/AssertionMessagesTest/touchingAWallNamesTheTimeTheSideAndTheTrace"
                + "/lab-Straight-seed3.trace"), trace);
        assertEquals(intoTheWall.trace(), Files.readString(trace));
        assertTrue(Files.isRegularFile(trace.resolveSibling("lab.arena")));
        String about = Files.readString(trace.resolveSibling("lab-Straight-seed3.txt"));
        assertTrue(about.contains("java -jar khepera-sim.jar run --arena lab --classpath "), about);
        assertTrue(about.contains(" --controller student.Straight --seed 3 --seconds 30 --set noise.robot=0\n"), about);
        assertTrue(about.contains("and open " + trace + "\n"), about);
        System.out.println(m);
    }

    @Test
    void aRegionNeverEnteredSaysHowNearTheRobotCame() throws Exception {
        String m = assertThrows(AssertionFailedError.class, () -> assertThat(headOn.robot(1)).entered("left_end")).getMessage();
        assertTrue(m.startsWith("Straight#1 never entered region 'left_end'.\n"), m);
        assertTrue(m.contains("  expected: to enter region 'left_end' (x 0.0..100.0 mm, y 0.0..600.0 mm)\n"), m);
        assertTrue(Pattern.compile("  happened: it did not in the 20.000 s the run lasted; nearest \\d+\\.\\d mm from it at"
                + " \\d+\\.\\d{3} s; ended at \\(").matcher(m).find(), m);
        assertTrue(Files.isRegularFile(tracePath(m)));
        System.out.println(m);
    }

    @Test
    void aRegionEnteredLateSaysWhenAndWhereTheRobotWasAtTheDeadline() {
        String m = assertThrows(AssertionFailedError.class,
                () -> assertThat(headOn.robot(0)).entered("middle").before(seconds(5))).getMessage();
        assertTrue(m.startsWith("Straight#0 entered region 'middle' too late, at 6."), m);
        assertTrue(m.contains("  expected: to enter region 'middle' (x 550.0..650.0 mm, y 0.0..600.0 mm) before 5.000 s\n"), m);
        assertTrue(Pattern.compile("  happened: first entered at 6\\.\\d{3} s; at 5\\.000 s the robot was at \\(\\d+\\.\\d, \\d+\\.\\d\\)"
                + " mm heading -?\\d+\\.\\d deg, \\d+\\.\\d mm from the region\\n").matcher(m).find(), m);
        System.out.println(m);
    }

    @Test
    void withSeveralRobotsTheMessageNamesTheRobotAndTheEarliestContact() {
        String touched = assertThrows(AssertionFailedError.class, () -> assertThat(headOn).neverTouched(ROBOT, LAMP)).getMessage();
        // Robot 3 drives into the lamp 62.5 mm ahead at 40 mm/s, long before robots 0 and 1 meet.
        assertTrue(touched.startsWith("Straight#3 touched a lamp at 1."), touched);
        assertTrue(touched.contains("\n  expected: never to touch a lamp or another robot\n"), touched);
        Run apart = Run.of(student.Straight.class).in(Fixtures.resource("head-on.arena")).seconds(3).run();
        String none = assertThrows(AssertionFailedError.class, () -> assertThat(apart).entered("left_end")).getMessage();
        assertTrue(none.startsWith("None of the 4 robots entered region 'left_end'.\n"), none);
        assertTrue(none.contains("; Straight#2 came nearest "), none);
    }

    @Test
    void aControllerThatThrewNamesTheExceptionItsLineAndTheTime() {
        Run run = Run.of(student.Thrower.class).in("lab").seconds(10).run();
        String m = assertThrows(AssertionFailedError.class, () -> assertThat(run).endedNormally()).getMessage();
        assertTrue(m.startsWith("Thrower's controller threw an exception at 2.000 s (" + Fixtures.line("Thrower", "throws here")
                + ").\n"), m);
        assertTrue(m.contains("  expected: the controller to run to the end of the run, or return by itself\n"), m);
        assertTrue(m.contains("  happened: threw java.lang.ArrayIndexOutOfBoundsException: Index 20 out of bounds for length 2;"), m);
        System.out.println(m);
    }

    @Test
    void scoresCapsAndRecordedRunsFailWithWhatTheyCounted() {
        Run maze = Run.of("WallFollower").in("maze-easy").seconds(5).run();
        String score = assertThrows(AssertionFailedError.class, () -> assertThat(maze).scoredAtLeast(90)).getMessage();
        assertTrue(score.startsWith("The run scored "), score);
        assertTrue(score.contains("  happened: score "), score);
        assertTrue(score.contains("(visit c*: "), score);
        String caps = assertThrows(AssertionFailedError.class, () -> assertThat(headOn).delivered(2, "left_end")).getMessage();
        assertTrue(caps.startsWith("1 cap lie in region 'left_end' at the end, fewer than 2."), caps);
        assertTrue(caps.contains("cap 0 first moved at 2."), caps);
        String none = assertThrows(AssertionFailedError.class, () -> assertThat(headOn).scoredAtLeast(0)).getMessage();
        assertTrue(none.startsWith("The arena head-on sets no task, so the run has no score."), none);
    }

    private static Path tracePath(String message) {
        Matcher m = Pattern.compile("\n  trace:    (\\S+)").matcher(message);
        assertTrue(m.find(), message);
        return Path.of(m.group(1));
    }
}
