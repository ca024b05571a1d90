package org.kheperasim.api;

/**
 * Where one of the robot's infrared sensors sits and which way it looks, as its robot file says:
 * x forward, y to the left, millimetres from the robot's centre; the heading in degrees
 * counter-clockwise from straight ahead.
 *
 * @param index the sensor's index, as used by {@code sensors[i]}
 * @param name its name on the robot ({@code FRONT_LEFT} on a Khepera, {@code ps7} on an e-puck)
 * @param xMm position forward of the centre, mm
 * @param yMm position left of the centre, mm
 * @param headingDeg viewing direction, degrees counter-clockwise from ahead
 */
public record SensorMount(int index, String name, double xMm, double yMm, double headingDeg) {

    /**
     * @param s a Khepera sensor
     * @return its mount
     */
    public static SensorMount of(IrSensor s) {
        return new SensorMount(s.index(), s.name(), s.xMm(), s.yMm(), s.headingDeg());
    }
}
