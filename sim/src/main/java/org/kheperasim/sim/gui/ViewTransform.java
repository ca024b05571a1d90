package org.kheperasim.sim.gui;

/**
 * Maps arena millimetres (y up) to screen pixels (y down) and back: a scale and the pixel where
 * the arena's origin (its lower-left corner) lands. Zoom keeps the point under the mouse still.
 */
public final class ViewTransform {
    /** Smallest and largest scale, pixels per mm. */
    public static final double MIN_SCALE = 0.05;
    /** Largest scale, pixels per mm. */
    public static final double MAX_SCALE = 40;

    private double scale = 0.5;
    private double originX;
    private double originY;

    /** @return pixels per mm */
    public double scale() {
        return scale;
    }

    /**
     * Fit an arena into a w × h pixel area with a margin, centred.
     *
     * @param width arena width, mm
     * @param height arena height, mm
     * @param w area width, px
     * @param h area height, px
     * @param margin px
     */
    public void fit(double width, double height, int w, int h, int margin) {
        double s = StrictMath.min((w - 2.0 * margin) / width, (h - 2.0 * margin) / height);
        scale = StrictMath.max(MIN_SCALE, StrictMath.min(MAX_SCALE, s));
        originX = (w - width * scale) / 2;
        originY = (h + height * scale) / 2;
    }

    /** @param x mm @return px */
    public double sx(double x) {
        return originX + x * scale;
    }

    /** @param y mm @return px */
    public double sy(double y) {
        return originY - y * scale;
    }

    /** @param px pixels @return mm */
    public double ax(double px) {
        return (px - originX) / scale;
    }

    /** @param py pixels @return mm */
    public double ay(double py) {
        return (originY - py) / scale;
    }

    /** @param mm a length @return pixels */
    public double len(double mm) {
        return mm * scale;
    }

    /**
     * Zoom about a screen point, which stays over the same arena point.
     *
     * @param px screen x
     * @param py screen y
     * @param factor scale multiplier (greater than 1 zooms in)
     */
    public void zoomAt(double px, double py, double factor) {
        double ax = ax(px);
        double ay = ay(py);
        scale = StrictMath.max(MIN_SCALE, StrictMath.min(MAX_SCALE, scale * factor));
        originX = px - ax * scale;
        originY = py + ay * scale;
    }

    /** @param dx pixels @param dy pixels: move the picture */
    public void pan(double dx, double dy) {
        originX += dx;
        originY += dy;
    }
}
