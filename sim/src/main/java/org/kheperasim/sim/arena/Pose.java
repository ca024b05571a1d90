package org.kheperasim.sim.arena;

/**
 * A robot's position and heading on the arena floor.
 *
 * @param x          centre of the robot, mm from the arena's left edge
 * @param y          centre of the robot, mm from the arena's bottom edge
 * @param headingDeg heading in degrees counter-clockwise, 0 = facing +x, 90 = facing +y
 */
public record Pose(double x, double y, double headingDeg) {

    /** @throws IllegalArgumentException if a component is NaN or infinite */
    public Pose {
        x = Numbers.finite("robot x", x);
        y = Numbers.finite("robot y", y);
        headingDeg = Numbers.finite("robot heading", headingDeg);
    }
}
