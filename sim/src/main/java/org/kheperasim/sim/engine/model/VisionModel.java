package org.kheperasim.sim.engine.model;

/**
 * The K213 linear vision turret's numbers: what its manual fixes (pixels, grey levels, field of
 * view) as constants, the rest read once from {@link Settings} ({@code vision.*}).
 *
 * <p>From the K213 Vision Turret User Manual (K-Team, version 1.2, 1999): the image sensor is a
 * 64 × 1 cell array giving one linear image of 64 pixels of 256 grey levels, numbered 0 to 63 from
 * the left of the field of view; the view angle is about 36°; the optics focus from 5 to 50 cm
 * ahead; and a second sensor, a light intensity detector, adapts the scanning speed to the light
 * (an iris).
 *
 * @param refreshNanos time between two images, ns ({@code vision.refreshMs})
 * @param noise per-pixel noise σ, grey levels, already scaled by {@code noise.reading}
 * @param wallGrey grey level of a wall in the room's light
 * @param capGrey grey level of a cap or ball
 * @param robotGrey grey level of another robot's body
 * @param backgroundGrey grey level of a pixel that sees nothing
 * @param lampGain how much brighter a lamp makes what it lights, at full exposure
 * @param fieldOfViewDeg the field of view, degrees ({@code vision.fieldOfViewDeg}; the manual's "about 36 degrees" by
 *     default)
 * @param lensMm where the lens is, mm ahead of the robot's centre ({@code vision.lensMm}; 20 by default, on the
 *     front of the turret, an estimate from its layout)
 */
public record VisionModel(long refreshNanos, double noise, double wallGrey, double capGrey, double robotGrey,
        double backgroundGrey, double lampGain, double fieldOfViewDeg, double lensMm) {

    /** Pixels in an image (the manual: 64). */
    public static final int PIXELS = 64;
    /** The brightest grey level (the manual: 256 levels). */
    public static final int MAX_GREY = 255;

    /** @param s the settings @return the turret's model */
    public static VisionModel of(Settings s) {
        return new VisionModel((long) StrictMath.rint(s.number("vision.refreshMs") * 1e6),
                s.number("vision.noise") * s.number("noise.reading"), s.number("vision.grey.wall"),
                s.number("vision.grey.cap"), s.number("vision.grey.robot"), s.number("vision.grey.background"),
                s.number("vision.lampGain"), s.number("vision.fieldOfViewDeg"), s.number("vision.lensMm"));
    }

    /**
     * @param pixel 0..63 @return the direction pixel {@code pixel} looks in, radians from straight ahead, left positive
     */
    public double bearing(int pixel) {
        return StrictMath.toRadians(fieldOfViewDeg / 2 - (pixel + 0.5) * fieldOfViewDeg / PIXELS);
    }
}
