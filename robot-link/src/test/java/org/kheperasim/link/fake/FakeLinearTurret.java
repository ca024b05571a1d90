package org.kheperasim.link.fake;

import java.util.Arrays;

/**
 * The fake robot's K213 linear vision turret, written from the turret's manual (K213 Vision Turret
 * User Manual, K-Team, 1999): a linear image of 64 pixels with 256 grey levels each, numbered 0 to 63
 * from the left of its field of view; the turret answers its own commands, the image ({@code N}),
 * the position of its brightest ({@code O}) and darkest ({@code P}) pixel, and its version
 * ({@code B}). A test sets what it sees; a span of pixels at a bearing stands for an object.
 */
public final class FakeLinearTurret {
    /** Pixels in an image. */
    public static final int PIXELS = 64;
    /** The turret's field of view, degrees. */
    public static final double VIEW_DEG = 36;

    private final int[] image = new int[PIXELS];

    /** @param grey what every pixel sees, 0..255 */
    public synchronized void fill(int grey) {
        Arrays.fill(image, clamp(grey));
    }

    /**
     * Put an object in view.
     *
     * @param bearingDeg where its middle is, degrees from straight ahead, left positive
     * @param widthDeg how wide it looks, degrees
     * @param grey its grey level, 0..255
     */
    public synchronized void object(double bearingDeg, double widthDeg, int grey) {
        for (int i = 0; i < PIXELS; i++) {
            double pixelDeg = VIEW_DEG / 2 - (i + 0.5) * VIEW_DEG / PIXELS;
            if (Math.abs(pixelDeg - bearingDeg) <= widthDeg / 2) {
                image[i] = clamp(grey);
            }
        }
    }

    /** @return the image: 64 grey levels, pixel 0 the leftmost */
    public synchronized int[] image() {
        return image.clone();
    }

    /** @return the first pixel of the highest grey level */
    public synchronized int brightest() {
        int best = 0;
        for (int i = 1; i < PIXELS; i++) {
            if (image[i] > image[best]) {
                best = i;
            }
        }
        return best;
    }

    /** @return the first pixel of the lowest grey level */
    public synchronized int darkest() {
        int best = 0;
        for (int i = 1; i < PIXELS; i++) {
            if (image[i] < image[best]) {
                best = i;
            }
        }
        return best;
    }

    private static int clamp(int grey) {
        return Math.max(0, Math.min(255, grey));
    }
}
