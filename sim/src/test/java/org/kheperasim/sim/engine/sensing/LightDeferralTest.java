package org.kheperasim.sim.engine.sensing;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.kheperasim.api.IrSensor;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.link.timing.PollStep;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Miscalibration;
import org.kheperasim.sim.engine.model.RobotModel;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.noise.CounterNoise;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.space.World;

/**
 * In an arena without lamps a light sample's values are computed only when somebody reads them:
 * its reply's length is known before. The values filled in later are those a sample taken at once
 * gives, and the length given beforehand is theirs, for robots of many calibrations (dark levels
 * near and far from a power of ten), with flicker made frequent and with none.
 */
class LightDeferralTest {

    @Test
    void aDeferredDarkSampleIsTheSampleTakenAtOnce() {
        World world = new World(ArenaFormat.parse("khepera-arena 1\nname dark\nsize 1219.2 1219.2\nrobot 300 600 0\n",
                "dark.arena"));
        String[] darkLevels = {"9.97", "99.8", "480", "996", "999.5"};
        int deferred = 0;
        int atOnce = 0;
        for (long key = 1; key <= 300; key++) {
            // Flicker made frequent, or none at all (as with noise.reading=0): a dark reading is then
            // the dark level itself.
            Settings settings = Settings.defaults().with("light.flickerRate", key % 2 == 0 ? "0" : "0.3")
                    .with("light.dark", darkLevels[(int) (key % darkLevels.length)]);
            RobotModel model = RobotModel.of(settings);
            Miscalibration calibration = new Miscalibration(model, new CounterNoise(key));
            CounterNoise[] noise = new CounterNoise[IrSensor.COUNT];
            for (int i = 0; i < noise.length; i++) {
                noise[i] = new CounterNoise(key * 17 + i);
            }
            LightSensing light = new LightSensing(world, new SensorPlacement(RobotTypes.KHEPERA1), model, calibration, noise);
            int chars = light.deferDark();
            if (chars < 0) {
                atOnce++; // a dark level near a power of ten: sampled at once
                continue;
            }
            deferred++;
            int[] now = new int[IrSensor.COUNT];
            int[] later = new int[IrSensor.COUNT];
            for (long sample = 0; sample < 200; sample++) {
                light.sample(300, 600, 1, 0, sample, now);
                light.fillDark(sample, later);
                assertArrayEquals(now, later, "robot " + key + ", sample " + sample);
                assertEquals(LinkTiming.replyChars(PollStep.LIGHT, now), 1 + IrSensor.COUNT + 2 + chars,
                        "robot " + key + ", sample " + sample + ": the reply's length given before the values");
            }
        }
        assertTrue(deferred > 100, "only " + deferred + " of 300 robots' dark samples were deferred");
        assertTrue(atOnce > 20, "only " + atOnce + " of 300 robots had a dark level near a power of ten");
    }
}
