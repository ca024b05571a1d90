package org.kheperasim.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.opentest4j.AssertionFailedError;

/**
 * What a run tells a test, checked against what the fixture controllers do: where a robot went, what it
 * touched and when, the regions it entered, the caps it moved, and how its controller ended, with the
 * line of the controller that threw or broke a rule.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RunTest {

    @Test
    void aRobotDrivenIntoAWallTouchesTheWallAtTheTimeItsSpeedGives() {
        Run run = Run.of(student.Straight.class).in("lab").seconds(30).seed(3).set("noise.robot", "0").run();
        RobotRun r = run.robot();
        assertEquals(SimTime.ofSeconds(30), run.duration());
        Contact first = r.contacts().get(0);
        assertEquals(Obstacle.WALL, first.what(), first.toString());
        assertEquals("FRONT", first.side());
        // From (609.6, 609.6) up to the top wall's face at 1211.2 mm less the body's 27.5 mm, at 5 units of 8 mm/s.
        double expected = (1211.2 - 27.5 - 609.6) / 40;
        assertEquals(expected, first.from().seconds(), 0.3, first.toString());
        assertEquals(SimTime.ofSeconds(30), first.to(), "it stays against the wall to the end");
        assertEquals(1183.7, r.finalPose().y(), 1.0);
        assertEquals(609.6, r.start().x(), 1e-9);
        assertEquals(601, r.path().size(), "a point every 50 ms, both ends included");
        assertTrue(r.regionsEntered().containsKey("upper_right"), r.regionsEntered().toString());
        assertEquals(Ending.Kind.RAN_TO_THE_END, r.ending().kind());
        assertTrue(r.ending().normal());
        assertEquals(1, r.collisions());
    }

    @Test
    void contactsSayWhatWasTouchedWhenRobotsCapsAndLampsMeet() {
        Run run = Run.of(student.Straight.class).in(Fixtures.resource("head-on.arena")).seconds(20).run();
        assertEquals(4, run.robots().size());
        assertEquals(Obstacle.ROBOT, run.robot(0).contacts().get(0).what(), run.robot(0).contacts().toString());
        assertEquals(Obstacle.ROBOT, run.robot(1).contacts().get(0).what());
        // They meet at once: the engine flags each robot's contact as it moves, so in the tick where the second one
        // in robot order closes the gap, the first is flagged a tick later, when it next moves.
        assertEquals(run.robot(0).contacts().get(0).from().nanos(), run.robot(1).contacts().get(0).from().nanos(),
                1_000_000L, "they meet at once");
        assertEquals(Obstacle.CAP, run.robot(2).contacts().get(0).what(), run.robot(2).contacts().toString());
        assertEquals(Obstacle.LAMP, run.robot(3).contacts().get(0).what(), run.robot(3).contacts().toString());
        assertEquals("Straight#2", run.robot(2).name());

        Cap cap = run.caps().get(0);
        assertTrue(cap.moved());
        assertEquals(150, cap.startX(), 1e-9);
        assertTrue(cap.endX() < 100, "pushed to the left wall: " + cap);
        assertEquals("left_end", cap.regionAtEnd().orElseThrow());
        assertEquals(1, run.capsIn("left_end"));
        // Robot 2 meets the cap when its centre is 27.5 + 9 mm from the cap's: (300 - 186.5) mm at 40 mm/s.
        assertEquals(113.5 / 40, cap.firstMoved().orElseThrow().seconds(), 0.3);

        SimTime middle = run.robot(0).entered("middle").orElseThrow();
        assertEquals((550 - 300) / 40.0, middle.seconds(), 0.3);
        assertEquals(SimTime.ZERO, run.robot(3).entered("middle").orElseThrow(), "it starts there");
        assertFalse(run.robot(2).entered("middle").isPresent());
    }

    @Test
    void aControllerThatThrowsEndsWithItsExceptionItsLineAndTheTime() {
        Run run = Run.of(student.Thrower.class).in("lab").seconds(10).run();
        Ending e = run.robot().ending();
        assertEquals(Ending.Kind.THREW, e.kind());
        assertEquals(Fixtures.line("Thrower", "throws here"), e.where().orElseThrow(), e.toString());
        assertTrue(e.message().contains("ArrayIndexOutOfBoundsException"), e.message());
        assertEquals(2.0, e.at().orElseThrow().seconds(), 0.05);
        assertEquals(2.0, run.duration().seconds(), 0.05, "a lone robot's run ends with its controller");
        assertFalse(e.normal());
    }

    @Test
    void aControllerThatCallsSystemExitBreaksARuleAtItsLine() {
        Ending e = Run.of(student.Exiter.class).in("lab").seconds(10).run().robot().ending();
        assertEquals(Ending.Kind.BROKE_A_RULE, e.kind(), e.toString());
        assertEquals(Fixtures.line("Exiter", "exits here"), e.where().orElseThrow(), e.toString());
        assertTrue(e.message().contains("System.exit(3)"), e.message());
    }

    @Test
    void aControllerThatStopsCallingTheApiHangsAtTheTimeItStopped() {
        Ending e = Run.of(student.Looper.class).in("lab").seconds(10).hangTimeout(0.5).run().robot().ending();
        assertEquals(Ending.Kind.HUNG, e.kind(), e.toString());
        assertEquals(1.0, e.at().orElseThrow().seconds(), 0.05);
    }

    @Test
    void aControllerThatTouchesFilesIsRefusedWithItsLine() {
        AssertionFailedError e = assertThrows(AssertionFailedError.class,
                () -> Run.of("student.Filer").in("lab").seconds(10).run());
        assertTrue(e.getMessage().startsWith("The controller could not run (" + Fixtures.line("Filer", "touches a file here")
                + "): "), e.getMessage());
        assertTrue(e.getMessage().contains("java.io.File"), e.getMessage());
    }

    @Test
    void theScoreIsTheArenasTasks() {
        Run run = Run.of("WallFollower").in("maze-easy").seconds(120).run();
        Score s = run.score();
        assertEquals(100, s.max());
        TaskScore visit = s.task("visit c*");
        assertEquals(visit.points(), s.points());
        assertTrue(visit.detail().endsWith("/9 regions"), visit.detail());
        long entered = run.robot().regionsEntered().keySet().stream().filter(n -> n.startsWith("c")).count();
        assertEquals(entered + "/9 regions", visit.detail());
        assertEquals(10 * s.points() / 100, s.scaledTo(10), 1e-9);
    }

    @Test
    void capsCarriedIntoARegionAreWhatTheDeliverTaskCounts() {
        Run run = Run.of("CapGatherer").in("two-rooms").seconds(450).seed(1).run();
        assertEquals(5, run.caps().size());
        assertEquals(run.capsIn("target") + "/5 caps", run.score().task("deliver caps into target").detail());
        assertTrue(run.capsIn("target") >= 3, run.caps().toString());
        for (Cap c : run.caps()) {
            if ("target".equals(c.regionAtEnd().orElse(""))) {
                assertTrue(c.moved() && c.displacementMm() > 100, c.toString());
                assertTrue(c.startX() < 609.6 && c.endX() > 680, "carried from the left room into the lit one: " + c);
            }
        }
        assertTrue(run.robot().contactsWith(Obstacle.CAP).size() > 0, "the gripper meets the caps it carries");
        KheperaAssertions.assertThat(run).delivered(run.capsIn("target"), "target");
    }

    @Test
    void badInputIsRefusedWithTheFix() {
        IllegalArgumentException noArena = assertThrows(IllegalArgumentException.class, () -> Run.of("WallFollower").in("mazee"));
        assertTrue(noArena.getMessage().contains("bundled arenas"), noArena.getMessage());
        IllegalArgumentException noController = assertThrows(IllegalArgumentException.class, () -> Run.of("MyControler"));
        assertTrue(noController.getMessage().contains("no controller class 'MyControler'"), noController.getMessage());
        IllegalArgumentException noSetting = assertThrows(IllegalArgumentException.class,
                () -> Run.of("WallFollower").in("lab").set("noise.readings", "0"));
        assertTrue(noSetting.getMessage().contains("noise.readings"), noSetting.getMessage());
        IllegalStateException noWhere = assertThrows(IllegalStateException.class, () -> Run.of("WallFollower").run());
        assertTrue(noWhere.getMessage().contains(".in(\"lab\")"), noWhere.getMessage());
        IllegalArgumentException noRobot = assertThrows(IllegalArgumentException.class,
                () -> Run.of("WallFollower").in("lab").robot(1, "Braitenberg").run());
        assertTrue(noRobot.getMessage().contains("robots 0..0"), noRobot.getMessage());
        IllegalArgumentException noRegion = assertThrows(IllegalArgumentException.class,
                () -> Run.of("WallFollower").in("lab").seconds(1).run().capsIn("goal"));
        assertEquals(List.of("lower_left", "lower_right", "upper_left", "upper_right").toString().replace("[", "")
                .replace("]", ""), noRegion.getMessage().replaceFirst(".*its regions are ", ""));
    }
}
