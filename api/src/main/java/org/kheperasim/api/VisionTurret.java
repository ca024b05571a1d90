package org.kheperasim.api;

import org.kheperasim.api.spi.RobotPort;

/**
 * The K213 linear vision turret: a one-dimensional camera on top of the robot that looks straight
 * ahead. Each image is a row of {@value #PIXELS} pixels spanning a field of view of about
 * {@value #FIELD_OF_VIEW_DEG}°, pixel 0 at its left edge and pixel 63 at its right, each a grey level
 * 0..{@value #MAX_GREY}, higher = brighter (K213 Vision Turret User Manual, K-Team, 1999). A lamp
 * saturates the pixels it covers; a white ball is bright, a wall dark.
 *
 * <p>Reading the turret asks the robot for a fresh image over the serial link, which takes time
 * (the reply carries 64 numbers: about 60 ms at 38400 baud), on the robot and in the simulator
 * alike. Use {@link #getBrightestPixel()} or {@link #getDarkestPixel()} when only the position of
 * the brightest or darkest point matters: their replies are short.
 */
public final class VisionTurret {
    /** Pixels in an image. */
    public static final int PIXELS = 64;
    /** The brightest grey level. */
    public static final int MAX_GREY = 255;
    /** The turret's field of view, degrees (about; pixel 0 looks 18° to the left of straight ahead). */
    public static final double FIELD_OF_VIEW_DEG = 36;

    private final RobotPort port;

    VisionTurret(RobotPort port) {
        this.port = port;
    }

    /**
     * @return a new image: {@value #PIXELS} grey levels, 0..255 (higher = brighter), index 0 the
     *     leftmost pixel
     */
    public int[] getImage() {
        return port.visionImage();
    }

    /** @return the index, 0..63, of the brightest pixel (the leftmost of equals): where a lamp is */
    public int getBrightestPixel() {
        return port.visionBrightest();
    }

    /** @return the index, 0..63, of the darkest pixel (the leftmost of equals) */
    public int getDarkestPixel() {
        return port.visionDarkest();
    }

    /**
     * @param pixel a pixel's index, 0..63
     * @return the direction that pixel looks in, degrees from straight ahead, positive to the left:
     *     +17.7 for pixel 0, −17.7 for pixel 63
     */
    public static double bearingDeg(int pixel) {
        return FIELD_OF_VIEW_DEG / 2 - (pixel + 0.5) * FIELD_OF_VIEW_DEG / PIXELS;
    }
}
