package org.kheperasim.sim.serve;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.engine.model.Settings;

/**
 * The served robot answers the K213 vision turret's commands as the turret does: {@code T,2,N} the
 * 64 pixels, {@code T,2,O} and {@code T,2,P} the brightest and darkest pixel's index, {@code T,2,B}
 * its version. The robot stands at (300, 600) facing +x; a lamp ahead and to its left, a wall behind it.
 */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ServedVisionTest {
    @Test
    void theTurretsCommandsAreAnsweredFromTheSimulatedTurret() throws Exception {
        String scene = "light 700 660 radius 15\nwall 1000 200 1000 1000 8\n";
        try (Served s = new Served(scene, Settings.defaults().withNoise(0), 1); LineClient c = s.client()) {
            String n = c.ask("T,2,N");
            assertTrue(n.startsWith("t,2,n,"), n);
            int[] image = Arrays.stream(n.substring(6).split(",")).mapToInt(Integer::parseInt).toArray();
            assertEquals(64, image.length, n);
            // The lamp at 8.6 degrees to the left, 2.1 degrees wide each side: pixels 13 to 19 or so.
            double bearing = Math.toDegrees(Math.atan2(60, 380));
            int middle = (int) Math.round((18 - bearing) / (36.0 / 64) - 0.5);
            assertEquals(255, image[middle], "the lamp's middle pixel saturates: " + n);
            assertEquals(10, image[50], "the wall on the right, in the room's light: " + n);
            int brightest = Integer.parseInt(c.ask("T,2,O").substring(6));
            assertEquals(255, image[brightest]);
            assertTrue(brightest <= middle && brightest > middle - 5, "the lamp's leftmost pixel: " + brightest);
            int darkest = Integer.parseInt(c.ask("T,2,P").substring(6));
            assertEquals(Arrays.stream(image).min().getAsInt(), image[darkest]);
            assertEquals("t,2,b,1,0", c.ask("T,2,B"));
        }
    }
}
