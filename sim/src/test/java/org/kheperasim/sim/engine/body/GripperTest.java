package org.kheperasim.sim.engine.body;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.sim.engine.body.CapPushTest.cap;
import static org.kheperasim.sim.engine.body.CapPushTest.engine;
import static org.kheperasim.sim.engine.body.CapPushTest.run;

import org.junit.jupiter.api.Test;
import org.kheperasim.api.ArmPosition;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.GripperTurret;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.CapView;

/** The gripper turret: arm timing, the optical barrier, grab, carry, drop. Robot at (300, 600) facing +x. */
class GripperTest {
    /** Where a gripped cap's centre is, with the robot at (300, 600) facing +x. */
    private static final double GRIP_X = 300 + GripperTurret.GRIP_MM;

    @Test
    void theArmTakesItsTravelTimeAndReportsWhereItLastRested() {
        SimRobot[] r = new SimRobot[1];
        Engine e = engine("", r);
        SimRobot robot = r[0];
        robot.controls().commandArm(0, ArmPosition.DOWN);
        run(e, 0.010);
        assertTrue(robot.gripper().armMoving(), "the command has arrived (its wire time is ~3 ms at 38400 baud)");
        run(e, 0.490);
        assertTrue(robot.gripper().armMoving());
        assertSame(ArmPosition.UP, robot.gripper().armRest(), "an arm still moving is not yet down");
        int halfway = robot.gripper().armPosition();
        assertTrue(halfway > 210 && halfway < 220, "about half of 180..250 after half of the 1 s travel: " + halfway);
        run(e, 0.520);
        assertFalse(robot.gripper().armMoving());
        assertSame(ArmPosition.DOWN, robot.gripper().armRest());
        assertEquals(GripperTurret.ARM_DOWN, robot.gripper().armPosition());

        Settings slow = Settings.defaults().withNoise(0).with("gripper.armTravelMs", "3000");
        Engine e2 = new Engine(new World(e.world().arena()), 1);
        SimRobot r2 = e2.addRobot("slow", new org.kheperasim.sim.arena.Pose(300, 600, 0), slow);
        r2.controls().commandArm(0, ArmPosition.DOWN);
        run(e2, 2.0);
        assertTrue(r2.gripper().armMoving(), "a 3 s arm is still travelling after 2 s");
    }

    /**
     * A robot creeping forward lowers its arm with a cap beside the left finger's line: the finger
     * comes down 4 mm into the cap and pushes it out as soon as the arm is low, though the robot has
     * moved far less than the gap between its body (the only part that reached out before) and the cap.
     */
    @Test
    void fingersComingDownBesideACapPushItAsideAtOnce() {
        SimRobot[] r = new SimRobot[1];
        double capY = 600 + GripperTurret.OPEN_HALF_GAP_MM + GripperTurret.FINGER_RADIUS_MM + 9 - 4;
        Engine e = engine("cap 340 " + capY + "\n", r);
        r[0].controls().commandSpeeds(0, 1, 1);
        r[0].controls().commandArm(0, ArmPosition.DOWN);
        run(e, 0.45);
        assertEquals(capY, cap(e, 0).y(), 1e-9, "the arm is not low yet");
        run(e, 0.2);
        assertTrue(r[0].x() - 300 < 6, "the robot has crept less than the body's 9.6 mm gap to the cap: " + (r[0].x() - 300));
        assertTrue(cap(e, 0).y() > capY + 3.9, "the finger pushed the cap out of its way: " + cap(e, 0).y());
    }

    /** The open fingers' tips reach farther than any other part of the lowered gripper without a large cap. */
    @Test
    void theGrippersReachIsItsFingertips() {
        double tip = StrictMath.hypot(GripperTurret.FINGER_TIP_MM, GripperTurret.OPEN_HALF_GAP_MM) + GripperTurret.FINGER_RADIUS_MM;
        assertEquals(tip, GripperTurret.REACH_MM, 1e-12);
        assertTrue(GripperTurret.REACH_MM > GripperTurret.GRIP_MM + 9, "a default cap held lies within the reach");
    }

    @Test
    void theFingersTakeTheirTimeToClose() {
        SimRobot[] r = new SimRobot[1];
        Engine e = engine("", r);
        r[0].controls().commandFingers(0, GripperState.CLOSED);
        run(e, 0.3);
        assertSame(GripperState.OPEN, r[0].gripper().fingers(), "still closing after 0.3 s of 0.4 s");
        run(e, 0.2);
        assertSame(GripperState.CLOSED, r[0].gripper().fingers());
        assertEquals(0, r[0].gripper().resistivity(), "empty fingers read nothing");
        assertFalse(r[0].gripper().objectPresent());
    }

    @Test
    void theOpticalBarrierSeesWhatCrossesTheLineBetweenTheFingers() {
        SimRobot[] r = new SimRobot[1];
        Engine e = engine("cap " + GRIP_X + " 610\n", r);
        assertFalse(r[0].gripper().objectPresent(), "with the arm up the barrier is above the cap");
        r[0].controls().commandArm(0, ArmPosition.DOWN);
        run(e, 1.1);
        assertTrue(r[0].gripper().objectPresent(), "a cap 10 mm off the axis still crosses the line");

        SimRobot[] empty = new SimRobot[1];
        Engine e2 = engine("cap " + GRIP_X + " 630\n", empty);
        empty[0].controls().commandArm(0, ArmPosition.DOWN);
        run(e2, 1.1);
        assertFalse(empty[0].gripper().objectPresent(), "a cap beside the fingers does not");

        SimRobot[] wall = new SimRobot[1];
        Engine e3 = engine("wall " + GRIP_X + " 500 " + GRIP_X + " 700 4\n", wall);
        wall[0].controls().commandArm(0, ArmPosition.DOWN);
        run(e3, 1.1);
        assertTrue(wall[0].gripper().objectPresent(), "anything breaking the line is detected, a wall too");
    }

    @Test
    void grabCarryThroughADoorwayAndDrop() {
        // A wall across the arena at x = 600 with a doorway between y = 540 and 660.
        SimRobot[] r = new SimRobot[1];
        Engine e = engine("cap " + GRIP_X + " 600\n"
                + "wall 600 0 600 540 8\nwall 600 660 600 1219.2 8\n"
                + "region target 700 400 1100 800\n", r);
        SimRobot robot = r[0];
        robot.controls().commandArm(0, ArmPosition.DOWN);
        run(e, 1.1);
        robot.controls().commandFingers(e.timeNanos(), GripperState.CLOSED);
        run(e, 0.5);
        assertSame(GripperState.CLOSED, robot.gripper().fingers());
        assertEquals(0, robot.gripper().heldCap(), "the cap between the fingers is held");
        assertTrue(robot.gripper().objectPresent());
        assertEquals(120, robot.gripper().resistivity(), "a held cap reads the cap's resistivity");
        assertEquals(OccupancyGridIds.FLOOR, e.world().grid().idAt(GRIP_X, 600), "a held cap leaves the grid");

        robot.controls().commandArm(e.timeNanos(), ArmPosition.UP);
        run(e, 1.1);
        robot.controls().commandSpeeds(e.timeNanos(), 5, 5);
        run(e, 14);   // about 540 mm: through the doorway into the other room
        robot.controls().commandSpeeds(e.timeNanos(), 0, 0);
        run(e, 0.1);
        assertTrue(robot.x() > 700, "through the doorway: x " + robot.x());
        CapView carried = cap(e, 0);
        assertTrue(carried.held());
        assertEquals(robot.x() + GripperTurret.GRIP_MM, carried.x(), 1e-6, "the cap travels in the gripper");
        assertEquals(0, e.world().capsInRegions().get("target"), "a held cap does not lie in a region");

        robot.controls().commandArm(e.timeNanos(), ArmPosition.DOWN);
        run(e, 1.1);
        robot.controls().commandFingers(e.timeNanos(), GripperState.OPEN);
        run(e, 0.5);
        CapView dropped = cap(e, 0);
        assertFalse(dropped.held());
        assertEquals(-1, robot.gripper().heldCap());
        assertEquals(0, robot.gripper().resistivity());
        assertEquals(robot.x() + GripperTurret.GRIP_MM, dropped.x(), 0.6, "dropped where the gripper is");
        assertEquals(600, dropped.y(), 0.6);
        assertTrue(OccupancyGridIds.isCap(e.world().grid().idAt(dropped.x(), dropped.y())), "back in the grid");
        assertEquals(1, e.world().capsInRegions().get("target"));
    }

    @Test
    void aCapDroppedOntoAnOccupiedSpotSettlesAtTheNearestFreeOne() {
        SimRobot[] r = new SimRobot[1];
        // Cap 0 at the grip point; cap 1 ahead, where the grip point will be after a short drive.
        Engine e = engine("cap " + GRIP_X + " 600\ncap " + (GRIP_X + 40) + " 600\n", r);
        SimRobot robot = r[0];
        robot.controls().commandArm(0, ArmPosition.DOWN);
        run(e, 1.1);
        robot.controls().commandFingers(e.timeNanos(), GripperState.CLOSED);
        run(e, 0.5);
        assertEquals(0, robot.gripper().heldCap());
        robot.controls().commandArm(e.timeNanos(), ArmPosition.UP);
        run(e, 1.1);
        robot.controls().commandSpeeds(e.timeNanos(), 2, 2);   // 16 mm/s: about 30 mm, short of touching cap 1 (40 mm)
        run(e, 1.9);
        robot.controls().commandSpeeds(e.timeNanos(), 0, 0);
        run(e, 0.1);
        double gripX = robot.x() + GripperTurret.GRIP_MM;
        CapView other = cap(e, 1);
        assertTrue(StrictMath.hypot(other.x() - gripX, other.y() - 600) < 18, "the spot under the gripper is taken");

        robot.controls().commandFingers(e.timeNanos(), GripperState.OPEN);
        run(e, 0.5);
        CapView dropped = cap(e, 0);
        assertFalse(dropped.held());
        double fromOther = StrictMath.hypot(dropped.x() - other.x(), dropped.y() - other.y());
        double fromBody = StrictMath.hypot(dropped.x() - robot.x(), dropped.y() - robot.y());
        assertTrue(fromOther >= 18 - 1e-9, "it does not overlap the other cap: " + fromOther);
        assertTrue(fromBody >= RobotTypes.KHEPERA1.body().radiusMm() + 9 - 1e-9, "nor the robot: " + fromBody);
        double moved = StrictMath.hypot(dropped.x() - gripX, dropped.y() - 600);
        assertTrue(moved < 20, "the nearest free spot is close by: " + moved + " mm away");
        assertEquals(cap(e, 1).x(), other.x(), 0.0, "the other cap was not disturbed");
    }

    /** Grid ids, named for the assertions. */
    private static final class OccupancyGridIds {
        static final int FLOOR = org.kheperasim.sim.arena.OccupancyGrid.FLOOR;

        static boolean isCap(int id) {
            return id >= org.kheperasim.sim.arena.OccupancyGrid.FIRST_CAP;
        }
    }
}
