package org.kheperasim.testing;

import java.util.Locale;

/**
 * Where a robot is and which way it faces. Millimetres from the arena's lower-left corner, x to the
 * right, y up; the heading in degrees counter-clockwise from +x (90 = facing up), as in arena files.
 *
 * @param x centre of the robot, mm
 * @param y centre of the robot, mm
 * @param headingDeg heading, degrees counter-clockwise from +x, as the simulator reports it (-180..180)
 */
public record Pose(double x, double y, double headingDeg) {

    /**
     * @param px a point's x, mm
     * @param py a point's y, mm
     * @return the distance from the robot's centre to that point, mm
     */
    public double distanceTo(double px, double py) {
        return StrictMath.hypot(px - x, py - y);
    }

    /** @return e.g. {@code (380.0, 610.2) mm heading 90.0 deg} */
    @Override
    public String toString() {
        return String.format(Locale.ROOT, "(%.1f, %.1f) mm heading %.1f deg", x, y, headingDeg);
    }
}
