package org.kheperasim.sim.engine.sensing;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.space.World;

/**
 * The K213 vision turret sees a lamp, a ball (cap) and a wall where they are: each pixel whose line
 * of sight passes well inside an object's outline (computed here from the geometry) shows that
 * object, and none well outside it does. Its noise is its own: reading it or not changes no other
 * reading.
 */
class LinearCameraTest {
    /** The robot at (300, 600) facing +x: its lens 20 mm ahead, at (320, 600). */
    private static final double LENS_X = 320;
    private static final double LENS_Y = 600;
    private static final String SCENE = """
            light 620 650 radius 15
            cap 500 560
            wall 900 300 900 900 8
            """;

    private static Engine engine(String items, Settings settings) {
        String text = "khepera-arena 1\nname eye\nsize 1219.2 1219.2\nrobot 300 600 0\n" + items;
        return new Engine(new World(ArenaFormat.parse(text, "eye.arena")), 5);
    }

    /** @return the bearing of pixel i, degrees, left positive */
    private static double bearing(int i) {
        return 18 - (i + 0.5) * 36.0 / 64;
    }

    /** @return {centre bearing, half width}, degrees, of a disc seen from the lens */
    private static double[] outline(double x, double y, double r) {
        double dx = x - LENS_X;
        double dy = y - LENS_Y;
        double d = Math.hypot(dx, dy);
        return new double[] {Math.toDegrees(Math.atan2(dy, dx)), Math.toDegrees(Math.asin(r / d))};
    }

    @Test
    void aLampABallAndAWallAppearWhereTheyAre() {
        Engine e = engine(SCENE, Settings.defaults().withNoise(0));
        SimRobot r = e.addRobot("r", new Pose(300, 600, 0), Settings.defaults().withNoise(0));
        e.runUntil(1_000_000L);
        int[] image = r.vision().image(e.timeNanos());
        double[] lamp = outline(620, 650, 15);
        double[] ball = outline(500, 560, 9);
        // A cell of the grid is 2.44 mm: an outline is true to about half a cell, a fraction of a degree here.
        double margin = 0.6;
        int lampPixels = 0;
        int ballPixels = 0;
        for (int i = 0; i < 64; i++) {
            double off = bearing(i);
            boolean inLamp = Math.abs(off - lamp[0]) < lamp[1] - margin;
            boolean nearLamp = Math.abs(off - lamp[0]) < lamp[1] + margin;
            boolean inBall = Math.abs(off - ball[0]) < ball[1] - margin;
            boolean nearBall = Math.abs(off - ball[0]) < ball[1] + margin;
            if (inLamp) {
                assertEquals(255, image[i], "pixel " + i + " looks at the lamp: " + Arrays.toString(image));
                lampPixels++;
            } else if (inBall) {
                assertTrue(image[i] >= 200 && image[i] < 255, "pixel " + i + " sees the white ball: " + Arrays.toString(image));
                ballPixels++;
            } else if (!nearLamp && !nearBall) {
                assertTrue(image[i] >= 10 && image[i] < 20, "pixel " + i + " sees the dark wall: " + Arrays.toString(image));
            }
        }
        assertTrue(lampPixels >= 6 && ballPixels >= 7, "the lamp (about 5.5 degrees) and the ball (about 6) cover pixels");
        int brightest = r.vision().brightest(e.timeNanos());
        assertEquals(lamp[0] + lamp[1], bearing(brightest), margin, "the brightest pixel: the lamp's left edge, the"
                + " leftmost of the saturated ones");
        assertTrue(lamp[0] > 0 && ball[0] < 0, "the lamp is left of ahead, the ball right");
    }

    @Test
    void aWallLitByALampLooksBrighterThanInTheRoomsLightAlone() {
        Settings exact = Settings.defaults().withNoise(0);
        Engine dark = engine("wall 400 300 400 900 8\n", exact);
        SimRobot a = dark.addRobot("r", new Pose(300, 600, 0), exact);
        Engine lit = engine("wall 400 300 400 900 8\nlight 380 560\n", exact);
        SimRobot b = lit.addRobot("r", new Pose(300, 600, 0), exact);
        int[] plain = a.vision().image(0);
        int[] bright = b.vision().image(0);
        assertEquals(10, plain[10], "the wall in the room's light: vision.grey.wall");
        assertTrue(bright[60] > plain[60], "near the lamp the wall is brighter: " + Arrays.toString(bright));
    }

    @Test
    void theImageChangesOncePerRefreshAndItsNoiseIsItsOwn() {
        Settings noisy = Settings.defaults().with("vision.noise", "3");
        Engine e1 = engine(SCENE, noisy);
        SimRobot r1 = e1.addRobot("r", new Pose(300, 600, 0), noisy);
        Engine e2 = engine(SCENE, noisy);
        SimRobot r2 = e2.addRobot("r", new Pose(300, 600, 0), noisy);
        assertNull(r1.vision().lastView(), "nothing is computed before a read");
        r1.controls().commandSpeeds(0, 3, 3);
        r2.controls().commandSpeeds(0, 3, 3);
        int[] previous = null;
        for (long ms = 10; ms <= 2000; ms += 10) {
            e1.runUntil(ms * 1_000_000L);
            e2.runUntil(ms * 1_000_000L);
            int[] img = r1.vision().image(e1.timeNanos());
            if (ms % 50 != 0 && previous != null) {
                assertArrayEquals(previous, img, "within a 50 ms period the image stays: " + ms + " ms");
            }
            if (ms % 50 == 0 && previous != null) {
                assertNotEquals(Arrays.toString(previous), Arrays.toString(img), "a new image each period: " + ms);
            }
            previous = img;
        }
        assertEquals(r2.x(), r1.x(), 0, "reading the turret does not move the robot differently");
        for (int i = 0; i < 8; i++) {
            assertEquals(r2.controls().visibleProximity(i), r1.controls().visibleProximity(i), "proximity " + i);
            assertEquals(r2.controls().visibleLight(i), r1.controls().visibleLight(i), "light " + i);
        }
        assertNull(r2.vision().lastView(), "the robot whose turret nobody read computed no image");
    }
}
