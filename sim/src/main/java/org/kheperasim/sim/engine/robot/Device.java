package org.kheperasim.sim.engine.robot;

import java.util.EnumSet;
import java.util.Set;

/**
 * The devices a robot may have, each reaching a controller through the same chain: a command of the
 * robot's protocol, a column (or line) of the trace, a method of the robot port, and a panel of the
 * window. {@code docs/adding-a-device.md} lists the files of that chain; {@code DeviceChainTest}
 * walks this list and fails for a device whose chain has a gap, so a new device starts here.
 */
public enum Device {
    /** The infrared sensors' reflected-light (proximity) readings. */
    PROXIMITY("infrared proximity"),
    /** The same sensors' ambient-light readings. */
    AMBIENT_LIGHT("ambient light"),
    /** The two wheels' speed controllers. */
    WHEEL_SPEEDS("wheel speeds"),
    /** The two wheels' position counters (encoders) and position moves. */
    WHEEL_POSITIONS("wheel position counters"),
    /** The gripper turret: arm, fingers and the object sensor ({@link RobotType.Turret#GRIPPER}). */
    GRIPPER("gripper turret"),
    /** The K213 linear vision turret ({@link RobotType.Turret#VISION}). */
    VISION("K213 vision turret");

    private final String what;

    Device(String what) {
        this.what = what;
    }

    /** @return what the device is, for messages, e.g. {@code gripper turret} */
    public String what() {
        return what;
    }

    /**
     * @param type a robot type
     * @return the devices a robot of that type has: every robot has its sensors and wheels, and the
     *     turrets its file names
     */
    public static Set<Device> of(RobotType type) {
        Set<Device> d = EnumSet.of(PROXIMITY, AMBIENT_LIGHT, WHEEL_SPEEDS, WHEEL_POSITIONS);
        if (type.hasGripper()) {
            d.add(GRIPPER);
        }
        if (type.hasVision()) {
            d.add(VISION);
        }
        return d;
    }
}
