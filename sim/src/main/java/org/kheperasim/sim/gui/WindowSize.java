package org.kheperasim.sim.gui;

import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;

/**
 * Where the window opens: at the size it had when last closed (or 1180 × 900 the first time), but
 * never larger than the screen's usable area (a 1366 × 768 laptop, a panel at the bottom), so the
 * console at the bottom is always on screen.
 */
final class WindowSize {
    /** Smaller than this the window is of no use; a smaller screen gets the whole screen. */
    private static final int MIN_WIDTH = 800;
    private static final int MIN_HEIGHT = 560;

    private WindowSize() {
    }

    /**
     * @param width the wanted width, px
     * @param height the wanted height, px
     * @return the bounds to open at: within the usable screen area, centred in it
     */
    static Rectangle fit(int width, int height) {
        Rectangle usable = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        int w = StrictMath.min(usable.width, StrictMath.max(StrictMath.min(MIN_WIDTH, usable.width), width));
        int h = StrictMath.min(usable.height, StrictMath.max(StrictMath.min(MIN_HEIGHT, usable.height), height));
        return new Rectangle(usable.x + (usable.width - w) / 2, usable.y + (usable.height - h) / 2, w, h);
    }
}
