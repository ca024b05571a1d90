package org.kheperasim.sim.engine.sensing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.space.World;

/** Ambient light: darkness with the paper's rare small flicker, lamps in range, walls in the way. */
class LightSensorTest {

    private static SimRobot robotIn(String items, Settings settings) {
        String text = "khepera-arena 1\nname light\nsize 1219.2 1219.2\nrobot 300 600 0\n" + items;
        Engine e = new Engine(new World(ArenaFormat.parse(text, "light.arena")), 3);
        SimRobot r = e.addRobot("r", new Pose(300, 600, 0), settings);
        e.runUntil(200_000_000L);
        return r;
    }

    @Test
    void inTheDarkEverySensorReadsTheDarkLevelWithRareSmallDeviations() {
        Settings settings = Settings.defaults().with("noise.robot", "0");
        Engine e = new Engine(new World(ArenaFormat.parse(
                "khepera-arena 1\nname dark\nsize 1219.2 1219.2\nrobot 300 600 0\n", "dark.arena")), 3);
        SimRobot r = e.addRobot("r", new Pose(300, 600, 0), settings);
        int readings = 0;
        int deviating = 0;
        long cycle = r.link().pollCycleNanos();
        for (int k = 1; k <= 3000; k++) {
            e.runUntil(k * cycle + cycle / 2);
            for (int i = 0; i < 8; i++) {
                int v = r.controls().visibleLight(i);
                readings++;
                assertTrue(StrictMath.abs(v - 480) <= 3, "darkness deviates by at most 0.5%: " + v);
                if (v != 480) {
                    deviating++;
                }
            }
        }
        double share = (double) deviating / readings;
        assertTrue(share > 0.005 && share < 0.04, "about 2% of dark readings deviate, saw " + share + " of " + readings);
    }

    @Test
    void aLampAheadBrightensTheFrontSensorsAndNotTheBackOnes() {
        SimRobot r = robotIn("light 420 600 range 400\n", Settings.defaults().withNoise(0));
        int front = r.controls().visibleLight(2);
        int back = r.controls().visibleLight(6);
        assertTrue(front < 300, "front sensors see the lamp 95 mm ahead: " + front);
        assertEquals(480, back, "back sensors face away from the lamp");
    }

    @Test
    void aWallBetweenTheLampAndTheRobotCastsAShadow() {
        SimRobot lit = robotIn("light 420 600 range 400\n", Settings.defaults().withNoise(0));
        SimRobot shaded = robotIn("light 420 600 range 400\nwall 380 500 380 700 8\n", Settings.defaults().withNoise(0));
        assertTrue(lit.controls().visibleLight(2) < 300);
        assertEquals(480, shaded.controls().visibleLight(2), "the wall hides the lamp");
    }

    @Test
    void aLampOutOfRangeIsDark() {
        SimRobot r = robotIn("light 1000 600 range 300\n", Settings.defaults().withNoise(0));
        assertEquals(480, r.controls().visibleLight(2));
    }
}
