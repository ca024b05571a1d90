package org.kheperasim.api.spi;

/**
 * Where the simulator has the robot, exactly (not as its sensors or its odometry would say):
 * what a backend that knows the truth gives {@link RobotPort#truePose()}. A real robot has no such
 * thing; its backend gives none.
 *
 * @param xMm the robot's centre, mm from the arena's left edge
 * @param yMm the robot's centre, mm from the arena's bottom edge (y up)
 * @param headingDeg heading, degrees counter-clockwise from +x
 * @param arenaWidthMm the arena's width, mm
 * @param arenaHeightMm the arena's height, mm (a screen's y, pointing down, is measured from its top)
 */
public record TruePose(double xMm, double yMm, double headingDeg, double arenaWidthMm, double arenaHeightMm) {
}
