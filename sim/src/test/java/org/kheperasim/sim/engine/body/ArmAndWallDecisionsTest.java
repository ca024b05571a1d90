package org.kheperasim.sim.engine.body;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.kheperasim.api.ArmPosition;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.space.World;

/**
 * Two differences from the WSU simulator, decided (docs/wsu-migration.md): the lowered gripper arm
 * stays out of the proximity beams unless {@code gripper.armInView} says otherwise; and a robot pressed
 * against a wall at an angle stays put while its wheels agree, and turns on the spot by their
 * difference, its encoders counting that turn and nothing of the blocked advance.
 */
class ArmAndWallDecisionsTest {
    private static Engine open(String items, Settings settings, SimRobot[] out, Pose start) {
        String text = "khepera-arena 1\nname t\nsize 1219.2 1219.2\nrobot 300 600 0\n" + items;
        Engine e = new Engine(new World(ArenaFormat.parse(text, "t.arena")), 1);
        out[0] = e.addRobot("r", start, settings);
        return e;
    }

    private static int[] proximityWithTheArmDown(String mode) {
        Settings s = Settings.defaults().withNoise(0).with("gripper.armInView", mode);
        SimRobot[] r = new SimRobot[1];
        Engine e = open("", s, r, new Pose(300, 600, 0));
        r[0].controls().commandArm(0, ArmPosition.DOWN);
        e.runUntil(1_500_000_000L);
        int[] v = new int[8];
        for (int i = 0; i < 8; i++) {
            v[i] = r[0].controls().visibleProximity(e.timeNanos(), i);
        }
        return v;
    }

    @Test
    void theLoweredArmIsOutOfTheBeamsUnlessASettingPutsItInFrontOfThem() {
        int[] none = proximityWithTheArmDown("none");
        for (int v : none) {
            assertTrue(v < 40, "open floor with the arm down reads the noise floor: " + Arrays.toString(none));
        }
        int[] front = proximityWithTheArmDown("front");
        assertTrue(front[2] > 1000 && front[3] > 1000, "the two sensors that look straight ahead: " + Arrays.toString(front));
        for (int i : new int[] {0, 1, 4, 5, 6, 7}) {
            assertTrue(front[i] < 40, "sensor " + i + " looks away from the arm: " + Arrays.toString(front));
        }
        int[] wsu = proximityWithTheArmDown("wsu");
        for (int i = 0; i < 6; i++) {
            assertTrue(wsu[i] > 1000, "the WSU simulator's sensors 0 to 5: " + Arrays.toString(wsu));
        }
        assertTrue(wsu[6] < 40 && wsu[7] < 40, "the rear sensors stay clear: " + Arrays.toString(wsu));
    }

    @Test
    void againstAWallAtAnAngleTheRobotStaysPutAndOnlyTurnsByItsWheelsDifference() {
        Settings exact = Settings.defaults().withNoise(0);
        SimRobot[] r = new SimRobot[1];
        // A wall across the way at x = 400, the robot heading 30 degrees towards it.
        Engine e = open("wall 400 300 400 900 8\n", exact, r, new Pose(340, 600, 30));
        SimRobot robot = r[0];
        robot.controls().commandSpeeds(0, 5, 5);
        e.runUntil(3_000_000_000L);
        assertTrue(robot.blocked(), "it reached the wall");
        double x = robot.x();
        double y = robot.y();
        int left = robot.encoderLeft();
        int right = robot.encoderRight();
        e.runUntil(6_000_000_000L);
        assertEquals(30, robot.headingDeg(), 1e-6, "with equal wheels it does not turn along the wall");
        assertEquals(x, robot.x(), 1e-6, "nor slide along it");
        assertEquals(y, robot.y(), 1e-6);
        assertEquals(left, robot.encoderLeft(), "the encoders stand still while it is blocked");
        assertEquals(right, robot.encoderRight());

        robot.controls().commandSpeeds(e.timeNanos(), 5, 3);
        e.runUntil(8_000_000_000L);
        // The difference, 1 unit each way (8 mm/s), turns it on the spot: 2 x 8 mm/s / 53 mm for about 2 s.
        double turned = robot.headingDeg() - 30;
        assertTrue(turned < -25 && turned > -40, "it turns right on the spot by the difference: " + turned);
        assertEquals(x, robot.x(), 0.5, "its centre stays against the wall");
        int dl = robot.encoderLeft() - left;
        int dr = robot.encoderRight() - right;
        assertEquals(-dl, dr, 2, "the encoders count the turn, one forward and one back, and no advance: " + dl + " " + dr);
        assertTrue(dl > 150, "the left wheel turns forward: " + dl);
    }
}
