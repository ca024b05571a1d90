package org.kheperasim.sim.engine.body;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.CapView;
import org.kheperasim.sim.engine.view.Contact;

/**
 * The push table: a robot driving at 5 units (40 mm/s) along +x from (300, 600) meets caps of
 * radius 9 mm. Which way each cap goes follows from the point of contact.
 */
class CapPushTest {
    private static final Settings EXACT = Settings.defaults().withNoise(0);
    private static final double TOUCH = RobotTypes.KHEPERA1.body().radiusMm() + 9;

    static Engine engine(String body, SimRobot[] out) {
        String text = "khepera-arena 1\nname t\nsize 1219.2 1219.2\nrobot 300 600 0\n" + body;
        Engine e = new Engine(new World(ArenaFormat.parse(text, "t.arena")), 1);
        out[0] = e.addRobot("r", new Pose(300, 600, 0), EXACT);
        return e;
    }

    static void run(Engine e, double seconds) {
        e.runUntil(e.timeNanos() + (long) (seconds * 1e9));
    }

    static CapView cap(Engine e, int i) {
        return e.world().caps().get(i);
    }

    /** Direction of a cap's displacement, degrees from +x (the robot's heading). */
    private static double direction(double x0, double y0, CapView c) {
        return StrictMath.toDegrees(StrictMath.atan2(c.y() - y0, c.x() - x0));
    }

    @Test
    void headOnPushCarriesTheCapStraightAhead() {
        SimRobot[] r = new SimRobot[1];
        Engine e = engine("cap 360 600\n", r);
        r[0].controls().commandSpeeds(0, 5, 5);
        run(e, 3);
        CapView c = cap(e, 0);
        assertTrue(c.x() > 360 + 60, "the cap is carried ahead: x " + c.x());
        assertEquals(0, direction(360, 600, c), 1.0, "straight ahead");
        // It rides on the front of the body, touching it.
        assertEquals(TOUCH, StrictMath.hypot(c.x() - r[0].x(), c.y() - r[0].y()), 0.5);
        assertFalse(r[0].blocked(), "a free cap does not stop the robot");
        assertEquals(0, r[0].collisions());
    }

    @ParameterizedTest(name = "cap {0} mm to the side")
    @CsvSource({"22, 1", "-22, -1", "32, 1", "-32, -1"})
    void glancingTouchSlidesTheCapToThatSide(double offset, int side) {
        SimRobot[] r = new SimRobot[1];
        Engine e = engine("cap 360 " + (600 + offset) + "\n", r);
        r[0].controls().commandSpeeds(0, 5, 5);
        run(e, 4);
        CapView c = cap(e, 0);
        double dir = direction(360, 600 + offset, c);
        // Pushed forward and out to its own side, never across the robot's path.
        assertTrue(side * dir > 10 && side * dir < 90, "pushed forward and to the side: " + dir + " deg");
        assertTrue(side * (c.y() - 600) >= TOUCH - 0.5, "slid clear of the path: y " + c.y());
        assertTrue(r[0].x() > c.x(), "the robot has passed it");
        assertEquals(600, r[0].y(), 1e-9, "a cap does not deflect the robot");
    }

    @Test
    void aCapPushedIntoAWallStopsThereAndBlocksTheRobot() {
        SimRobot[] r = new SimRobot[1];
        // The wall's face is at x = 496.
        Engine e = engine("cap 360 600\nwall 500 300 500 900 8\n", r);
        r[0].controls().commandSpeeds(0, 5, 5);
        run(e, 6);
        CapView c = cap(e, 0);
        assertEquals(496 - 9, c.x(), 2.5, "the cap stops at the wall's face");
        assertTrue(e.world().field().preciseClearance(c.x(), c.y()) >= 9 - 1e-6, "the cap never enters the wall");
        assertTrue(r[0].blocked(), "the jammed cap blocks the robot");
        assertEquals(1, r[0].collisions());
        assertSame(Contact.FRONT, r[0].contact());
        assertEquals(c.x() - TOUCH, r[0].x(), 0.5);
        int enc = r[0].encoderLeft();
        run(e, 1);
        assertEquals(enc, r[0].encoderLeft(), "the encoders stall as against a wall");

        r[0].controls().commandSpeeds(e.timeNanos(), -5, -5);
        run(e, 1);
        assertFalse(r[0].blocked(), "it may back away");
        assertEquals(c.x(), cap(e, 0).x(), 0.0, "the cap stays at the wall");
    }

    @Test
    void twoCapsInARowAreBothPushedAhead() {
        SimRobot[] r = new SimRobot[1];
        Engine e = engine("cap 360 600\ncap 379 600\n", r);
        r[0].controls().commandSpeeds(0, 5, 5);
        run(e, 3);
        CapView first = cap(e, 0);
        CapView second = cap(e, 1);
        assertTrue(first.x() > 400, "the first cap moved ahead: " + first.x());
        assertTrue(second.x() > first.x() + 17.9, "the second stays ahead of the first: " + second.x());
        assertEquals(0, direction(379, 600, second), 1.0, "straight ahead");
        assertTrue(StrictMath.hypot(second.x() - first.x(), second.y() - first.y()) >= 18 - 1e-6,
                "caps never overlap");
        assertFalse(r[0].blocked());
    }

    @Test
    void aRowOfCapsAgainstAWallBlocksTheRobot() {
        SimRobot[] r = new SimRobot[1];
        Engine e = engine("cap 360 600\ncap 379 600\nwall 440 300 440 900 8\n", r);
        r[0].controls().commandSpeeds(0, 5, 5);
        run(e, 5);
        assertTrue(r[0].blocked());
        CapView first = cap(e, 0);
        CapView second = cap(e, 1);
        assertEquals(436 - 9, second.x(), 2.5);
        assertTrue(second.x() - first.x() >= 18 - 1e-6);
    }

    @Test
    void proximitySensorsSeeACap() {
        SimRobot[] r = new SimRobot[1];
        Engine withCap = engine("cap 345 600\n", r);
        run(withCap, 0.1);
        int seen = StrictMath.max(r[0].controls().visibleProximity(2), r[0].controls().visibleProximity(3));
        Engine without = engine("", r);
        run(without, 0.1);
        int empty = StrictMath.max(r[0].controls().visibleProximity(2), r[0].controls().visibleProximity(3));
        assertTrue(seen > 300, "a cap 11 mm ahead reads high: " + seen);
        assertTrue(empty < 50, "nothing ahead reads low: " + empty);
    }
}
