package org.kheperasim.sim.engine.view;

import java.util.Arrays;

/**
 * The last image a robot's K213 vision turret gave its controller, for listeners (the window's
 * image strip, the trace). Immutable.
 *
 * @param robot the robot's index
 * @param takenNanos when the turret took it, ns of simulated time
 * @param pixels the 64 grey levels, 0..255, index 0 the leftmost
 */
public record VisionView(int robot, long takenNanos, int[] pixels) {
    /** Copies the pixels. */
    public VisionView {
        pixels = pixels.clone();
    }

    /** @return a copy of the pixels */
    @Override
    public int[] pixels() {
        return pixels.clone();
    }

    /** @param i a pixel's index, 0..63 @return its grey level, 0..255 */
    public int pixel(int i) {
        return pixels[i];
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof VisionView v && v.robot == robot && v.takenNanos == takenNanos
                && Arrays.equals(v.pixels, pixels);
    }

    @Override
    public int hashCode() {
        return robot * 31 + Long.hashCode(takenNanos) * 17 + Arrays.hashCode(pixels);
    }
}
