package org.kheperasim.sim.engine.space;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.view.CapView;
import org.kheperasim.sim.engine.view.Contact;

/**
 * Robots are bodies to each other: they stop on contact as at a wall and never overlap, their
 * beams see each other's bodies, and a cap pushed against a robot stops there.
 */
class RobotBodiesTest {
    private static final Settings EXACT = Settings.defaults().withNoise(0);
    private static final double R = RobotTypes.KHEPERA1.body().radiusMm();

    private static Engine engine(String body) {
        String text = "khepera-arena 1\nname t\nsize 1219.2 1219.2\nrobot 300 600 0\n" + body;
        return new Engine(new World(ArenaFormat.parse(text, "t.arena")), 1);
    }

    private static double gap(SimRobot a, SimRobot b) {
        return StrictMath.hypot(a.x() - b.x(), a.y() - b.y()) - 2 * R;
    }

    @Test
    void twoRobotsDrivenHeadOnStopAtContactAndNeverOverlap() {
        Engine e = engine("");
        SimRobot a = e.addRobot("a", new Pose(300, 600, 0), EXACT);
        SimRobot b = e.addRobot("b", new Pose(500, 605, 180), EXACT);
        a.controls().commandSpeeds(0, 5, 5);
        b.controls().commandSpeeds(0, 5, 5);
        double closest = Double.POSITIVE_INFINITY;
        for (int ms = 0; ms < 6000; ms += 10) {
            e.runUntil(e.timeNanos() + 10_000_000L);
            closest = StrictMath.min(closest, gap(a, b));
        }
        assertTrue(closest >= -1e-6, "they never overlap: closest gap " + closest + " mm");
        assertEquals(0, gap(a, b), 0.05, "they stopped touching");
        assertTrue(a.blocked() && b.blocked(), "both are blocked");
        assertEquals(Contact.FRONT, a.contact(), "a touches b at its front");
        assertEquals(Contact.FRONT, b.contact(), "b touches a at its front");
        assertEquals(1, a.collisions());
        assertEquals(1, b.collisions());
        // The encoders stall: a has driven no farther than to the contact (about 72 mm, each half the gap).
        double aTravel = a.x() - 300;
        assertTrue(aTravel > 60 && aTravel < 80, "a drove to the contact only: " + aTravel);
    }

    @Test
    void aRobotBackingAwayFromAnotherIsFree() {
        Engine e = engine("");
        SimRobot a = e.addRobot("a", new Pose(300, 600, 0), EXACT);
        SimRobot b = e.addRobot("b", new Pose(355, 600, 0), EXACT);
        a.controls().commandSpeeds(0, -3, -3);
        e.runUntil(1_000_000_000L);
        assertTrue(a.x() < 290, "it backed away from the robot it touched: x " + a.x());
        assertEquals(0, a.collisions());
    }

    @Test
    void theFrontSensorsSeeAnotherRobot20mmAhead() {
        Engine alone = engine("");
        SimRobot solo = alone.addRobot("a", new Pose(300, 600, 0), EXACT);
        alone.runUntil(200_000_000L);
        Engine e = engine("");
        SimRobot a = e.addRobot("a", new Pose(300, 600, 0), EXACT);
        e.addRobot("b", new Pose(300 + 2 * R + 20, 600, 0), EXACT);
        e.runUntil(200_000_000L);
        // Sensors 2 and 3 look straight ahead.
        for (int i : new int[] {2, 3}) {
            int seen = a.controls().visibleProximity(i);
            int empty = solo.controls().visibleProximity(i);
            assertTrue(seen > empty + 200, "front sensor " + i + " sees the robot: " + seen + " (nothing ahead: " + empty + ")");
        }
        int back = a.controls().visibleProximity(6);
        assertTrue(back < 100, "the back sensors see nothing: " + back);
    }

    @Test
    void aRobotsBodyReflectsLessThanAWallAtTheSameDistance() {
        Engine walled = engine("wall 367.5 300 367.5 900 8\n");
        SimRobot w = walled.addRobot("a", new Pose(300, 600, 0), EXACT);
        walled.runUntil(200_000_000L);
        Engine e = engine("");
        SimRobot a = e.addRobot("a", new Pose(300, 600, 0), EXACT);
        // The other robot's nearest point is where the wall's face is: 36 mm ahead of the sensors' rim.
        e.addRobot("b", new Pose(363.5 + R, 600, 0), EXACT);
        e.runUntil(200_000_000L);
        int wall = StrictMath.max(w.controls().visibleProximity(2), w.controls().visibleProximity(3));
        int robot = StrictMath.max(a.controls().visibleProximity(2), a.controls().visibleProximity(3));
        assertTrue(robot < wall && robot > 0.5 * wall, "robot (reflectance 0.8, and round) " + robot + " vs wall " + wall);
    }

    @Test
    void aCapPushedAgainstAStationaryRobotStopsThere() {
        Engine e = engine("cap 360 600\n");
        SimRobot pusher = e.addRobot("a", new Pose(300, 600, 0), EXACT);
        SimRobot still = e.addRobot("b", new Pose(460, 600, 0), EXACT);
        pusher.controls().commandSpeeds(0, 5, 5);
        e.runUntil(6_000_000_000L);
        CapView c = e.world().caps().get(0);
        double capToStill = StrictMath.hypot(c.x() - still.x(), c.y() - still.y());
        assertTrue(capToStill >= R + 9 - 1e-6, "the cap does not enter the robot: " + capToStill);
        assertEquals(R + 9, capToStill, 0.5, "it stopped touching the robot");
        assertTrue(pusher.blocked(), "the cap, held by the robot, blocks the pusher");
        assertEquals(460, still.x(), 1e-9, "the stationary robot was not moved");
    }
}
