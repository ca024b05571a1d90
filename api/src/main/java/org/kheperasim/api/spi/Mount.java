package org.kheperasim.api.spi;

/**
 * Where a sensor sits on the robot and which way it looks, as a backend reports it (the student
 * API shows it as a {@code SensorMount}): x forward, y to the left, millimetres from the robot's
 * centre; the heading in degrees counter-clockwise from straight ahead.
 *
 * @param name its name on the robot ({@code FRONT_LEFT} on a Khepera, {@code ps7} on an e-puck)
 * @param xMm position forward of the centre, mm
 * @param yMm position left of the centre, mm
 * @param headingDeg viewing direction, degrees counter-clockwise from ahead
 */
public record Mount(String name, double xMm, double yMm, double headingDeg) {
}
