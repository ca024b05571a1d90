package org.kheperasim.api;

import org.kheperasim.api.spi.RobotPort;

/**
 * One of the robot's infrared sensors (the Khepera's eight, or those of its robot file). A live
 * view: the object a controller fetched once keeps returning fresh readings, as the robot's poll
 * loop (or the simulator) refreshes them.
 */
public final class Sensor {
    private final RobotPort port;
    private final SensorMount mount;

    Sensor(RobotPort port, SensorMount mount) {
        this.port = port;
        this.mount = mount;
    }

    /**
     * @return the latest proximity reading, 0 to about {@link #getMaxDistValue()} (noise may take a sensor
     *     that does not saturate a little above it): higher is nearer (on a Khepera,
     *     0..1023: about 1000 touching a wall, about 600 at 15–20 mm, a few tens beyond 50 mm)
     */
    public int getDistValue() {
        return port.proximity(mount.index());
    }

    /**
     * @return the largest reading this robot's proximity sensors give, counts (an obstacle at the distance
     *     that reads highest, noise aside): 1023 on a Khepera, whose sensors saturate at the top of their
     *     scale; 2976 on the bundled e-puck, whose 12-bit scale (4095) its sensors do not fill. A controller
     *     that takes {@link #getDistValue()} as a fraction of it runs on every robot
     */
    public int getMaxDistValue() {
        return port.maxProximity();
    }

    /** @return the latest ambient-light reading, 0..1023: lower is brighter (about 480 in the dark) */
    public int getLightValue() {
        return port.ambientLight(mount.index());
    }

    /** @return this sensor's index, 0 to the robot's sensor count - 1 (0..7 on a Khepera) */
    public int getIndex() {
        return mount.index();
    }

    /**
     * @return the Khepera sensor of this index (on another robot the one at the same place in the
     *     Khepera's order: see docs/robot-files.md)
     * @throws IllegalStateException for an index the Khepera does not have (a ninth sensor and beyond)
     */
    public IrSensor getPosition() {
        if (mount.index() >= IrSensor.COUNT) {
            throw new IllegalStateException("sensor " + mount.index() + " (" + mount.name() + ") has no Khepera name;"
                    + " use getMount() for where it sits");
        }
        return IrSensor.of(mount.index());
    }

    /** @return where this sensor sits on its robot, which way it looks, and its name there */
    public SensorMount getMount() {
        return mount;
    }

    @Override
    public String toString() {
        return "Sensor " + mount.index() + " (" + mount.name() + ")";
    }
}
