package org.kheperasim.sim.engine.view;

import java.util.Arrays;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;

/**
 * An immutable picture of one robot at one instant.
 *
 * @param id the robot's index
 * @param name the robot's name
 * @param x position, mm
 * @param y position, mm
 * @param headingDeg heading, degrees counter-clockwise from +x
 * @param speedLeft speed in effect on the left wheel, units
 * @param speedRight speed in effect on the right wheel, units
 * @param encoderLeft the robot's left position counter, pulses
 * @param encoderRight the robot's right position counter, pulses
 * @param contact which side touches an obstacle
 * @param proximity the proximity values the controller sees, 0..1023
 * @param light the light values the controller sees, 0..1023
 * @param collisions collisions so far
 * @param distanceMm path length so far, mm
 * @param controller the controller's state, as text (running, finished, failed, hung, none)
 * @param gripper the gripper turret's state
 * @param leds the robot's two LEDs as set by the protocol's {@code L} command: bit 0 the lateral LED,
 *     bit 1 the front LED, 1 = on (always 0 in a run with a controller: the api has no LEDs)
 * @param type the robot's type: what the window draws (body, sensors) and the trace names
 */
public record RobotView(int id, String name, double x, double y, double headingDeg, int speedLeft, int speedRight,
        int encoderLeft, int encoderRight, Contact contact, int[] proximity, int[] light, int collisions,
        double distanceMm, String controller, GripperView gripper, int leds, RobotType type) {

    /** Copies the arrays, so the view cannot change. */
    public RobotView {
        proximity = proximity.clone();
        light = light.clone();
    }

    /** A view of a {@link RobotTypes#KHEPERA1}. */
    public RobotView(int id, String name, double x, double y, double headingDeg, int speedLeft, int speedRight,
            int encoderLeft, int encoderRight, Contact contact, int[] proximity, int[] light, int collisions,
            double distanceMm, String controller, GripperView gripper, int leds) {
        this(id, name, x, y, headingDeg, speedLeft, speedRight, encoderLeft, encoderRight, contact, proximity, light,
                collisions, distanceMm, controller, gripper, leds, RobotTypes.KHEPERA1);
    }

    /** @param led 0 lateral, 1 front @return true when that LED is on */
    public boolean led(int led) {
        return (leds & (1 << led)) != 0;
    }

    /** @return a copy of the proximity values */
    @Override
    public int[] proximity() {
        return proximity.clone();
    }

    /** @return a copy of the light values */
    @Override
    public int[] light() {
        return light.clone();
    }

    /** @return how many sensors the robot has */
    public int sensorCount() {
        return proximity.length;
    }

    /** @param i sensor index, 0 to {@link #sensorCount()} - 1 @return its proximity value */
    public int proximity(int i) {
        return proximity[i];
    }

    /** @param i sensor index, 0 to {@link #sensorCount()} - 1 @return its light value */
    public int light(int i) {
        return light[i];
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof RobotView v && v.id == id && v.name.equals(name) && v.x == x && v.y == y
                && v.headingDeg == headingDeg && v.speedLeft == speedLeft && v.speedRight == speedRight
                && v.encoderLeft == encoderLeft && v.encoderRight == encoderRight && v.contact == contact
                && Arrays.equals(v.proximity, proximity) && Arrays.equals(v.light, light)
                && v.collisions == collisions && v.distanceMm == distanceMm && v.controller.equals(controller)
                && v.gripper.equals(gripper) && v.leds == leds;
    }

    @Override
    public int hashCode() {
        return Double.hashCode(x) * 31 + Double.hashCode(y) + Arrays.hashCode(proximity);
    }
}
