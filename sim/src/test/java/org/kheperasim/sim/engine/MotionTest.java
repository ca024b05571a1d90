package org.kheperasim.sim.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.Contact;

/** Differential drive in Khepera units, encoders, and what happens against a wall. */
class MotionTest {
    private static final String OPEN = "khepera-arena 1\nname open\nsize 1219.2 1219.2\nrobot 300 600 0\n"
            + "wall 900 100 900 1100 8\n";
    private static final Settings EXACT = Settings.defaults().withNoise(0);

    private static Engine engine(SimRobot[] out, Pose start) {
        Engine e = new Engine(new World(ArenaFormat.parse(OPEN, "open.arena")), 1);
        out[0] = e.addRobot("r", start, EXACT);
        return e;
    }

    private static void run(Engine e, double seconds) {
        long end = e.timeNanos() + (long) (seconds * 1e9);
        while (e.timeNanos() < end) {
            e.step();
        }
    }

    @Test
    void straightAtFiveUnitsCovers40MillimetresASecond() {
        SimRobot[] r = new SimRobot[1];
        Engine e = engine(r, new Pose(300, 600, 0));
        r[0].controls().commandSpeeds(0, 5, 5);
        run(e, 5);
        // The command takes its wire time (~2.4 ms at 38400 baud) to reach the robot.
        double delay = r[0].link().speedCommandDelayNanos(5, 5) / 1e9;
        double expected = 5 * 8 * (5 - StrictMath.ceil(delay * 1000) / 1000);
        assertEquals(300 + expected, r[0].x(), 1e-6);
        assertEquals(600, r[0].y(), 1e-9);
        assertEquals(expected / 0.08, r[0].encoderLeft(), 1.0);
        assertEquals(r[0].encoderLeft(), r[0].encoderRight());
    }

    @Test
    void opposedWheelsTurnOnTheSpot() {
        SimRobot[] r = new SimRobot[1];
        Engine e = engine(r, new Pose(300, 600, 0));
        r[0].controls().commandSpeeds(0, -3, 3);
        run(e, 1.0);
        double seconds = 1.0 - StrictMath.ceil(r[0].link().speedCommandDelayNanos(-3, 3) / 1e6) / 1000;
        double expectedDeg = StrictMath.toDegrees(2 * 24.0 * seconds / RobotTypes.KHEPERA1.drive().wheelBaseMm());
        assertEquals(expectedDeg, r[0].headingDeg(), 1e-6);
        assertEquals(300, r[0].x(), 1e-9);
        assertEquals(600, r[0].y(), 1e-9);
        assertEquals(-r[0].encoderLeft(), r[0].encoderRight(), 1);
    }

    @Test
    void encodersStallWhileTheRobotIsPushedAgainstAWall() {
        SimRobot[] r = new SimRobot[1];
        Engine e = engine(r, new Pose(800, 600, 0));
        r[0].controls().commandSpeeds(0, 3, 3);
        run(e, 8);
        assertTrue(r[0].blocked(), "the robot should be stopped by the wall");
        assertSame(Contact.FRONT, r[0].contact());
        assertEquals(3, r[0].speedLeft());
        assertEquals(1, r[0].collisions());
        int left = r[0].encoderLeft();
        int right = r[0].encoderRight();
        double x = r[0].x();
        run(e, 3);
        assertEquals(left, r[0].encoderLeft(), "left encoder must not count while blocked");
        assertEquals(right, r[0].encoderRight(), "right encoder must not count while blocked");
        assertEquals(x, r[0].x(), 0.0);
        // The wall's face is at 896 mm (±1 cell); the body stops touching it.
        assertEquals(896 - RobotTypes.KHEPERA1.body().radiusMm(), r[0].x(), 2.5);

        // It may back away: the encoders count again.
        r[0].controls().commandSpeeds(e.timeNanos(), -3, -3);
        run(e, 1);
        assertTrue(r[0].encoderLeft() < left - 250, "backing away counts down");
        assertSame(Contact.NONE, r[0].contact());
    }

    @Test
    void turningAwayFromAWallIsAllowedWhileTouching() {
        SimRobot[] r = new SimRobot[1];
        Engine e = engine(r, new Pose(800, 600, 0));
        r[0].controls().commandSpeeds(0, 3, 3);
        run(e, 8);
        assertTrue(r[0].blocked());
        r[0].controls().commandSpeeds(e.timeNanos(), -3, 3);
        run(e, 2);
        assertTrue(r[0].headingDeg() > 80, "turned on the spot: " + r[0].headingDeg());
        r[0].controls().commandSpeeds(e.timeNanos(), 3, 3);
        run(e, 2);
        assertTrue(r[0].y() > 640, "drives off along the wall: y = " + r[0].y());
    }
}
