package org.kheperasim.api;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The spike filter: a single spike never gets through a median of three; a real change does, a reading later. */
class SensorFilterTest {
    @Test
    void aSingleSpikeIsIgnoredAndNamed() {
        SensorFilter f = new SensorFilter(1, 3, 200);
        for (int k = 0; k < 5; k++) {
            assertEquals(20, f.add(0, 20));
        }
        assertEquals(20, f.add(0, 1023), "a spike does not get through");
        assertTrue(f.lastWasSpike(0));
        assertEquals(21, f.add(0, 21), "the median of 20, 1023, 21");
        assertFalse(f.lastWasSpike(0));
        assertEquals(1, f.spikes());
    }

    @Test
    void aRealChangeGetsThroughOneReadingLate() {
        SensorFilter f = new SensorFilter(1, 3, 200);
        f.add(0, 20);
        f.add(0, 20);
        assertEquals(20, f.add(0, 900), "the first reading of a change looks like a spike");
        assertEquals(900, f.add(0, 900), "the second is believed");
        SensorFilter five = new SensorFilter(1, 5, 200);
        for (int k = 0; k < 5; k++) {
            five.add(0, 20);
        }
        assertEquals(20, five.add(0, 900));
        assertEquals(20, five.add(0, 900), "a window of five ignores two in a row");
        assertEquals(900, five.add(0, 900));
    }

    @Test
    void noisyReadingsWithRareSpikesComeOutClose() {
        Random r = new Random(7);
        SensorFilter f = new SensorFilter();
        int badRaw = 0;
        int badFiltered = 0;
        for (int k = 0; k < 10_000; k++) {
            int[] raw = new int[8];
            for (int i = 0; i < 8; i++) {
                int truth = 100 + 50 * i;
                raw[i] = r.nextInt(1000) < 5 ? 1023 : truth + (int) StrictMath.round(r.nextGaussian() * 10);
            }
            int[] out = f.add(raw);
            for (int i = 0; i < 8; i++) {
                badRaw += StrictMath.abs(raw[i] - (100 + 50 * i)) > 60 ? 1 : 0;
                badFiltered += StrictMath.abs(out[i] - (100 + 50 * i)) > 60 ? 1 : 0;
            }
        }
        assertTrue(badRaw > 300, "the input had spikes: " + badRaw);
        // Only two spikes in a row on one sensor (about 0.5 % squared of the readings) get through.
        assertTrue(badFiltered <= badRaw / 50, badFiltered + " of " + badRaw + " spikes came through");
        assertTrue(f.spikes() > 200 && f.spikes() < 600, "about 0.5 % of 80,000 readings were spikes: " + f.spikes());
    }

    @Test
    void resetForgetsAndBadSettingsAreRefused() {
        SensorFilter f = new SensorFilter(2, 3, 100);
        f.add(new int[] {5, 6});
        assertArrayEquals(new int[] {5, 6}, new int[] {f.value(0), f.value(1)});
        f.reset();
        assertEquals(0, f.value(0));
        assertEquals(0, f.spikes());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new SensorFilter(8, 4, 100));
        assertTrue(e.getMessage().contains("odd"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new SensorFilter(0, 3, 100));
    }
}
