package org.kheperasim.api;

import org.kheperasim.api.spi.RobotPort;

/**
 * One of the Khepera's eight infrared sensors. A live view: the object a controller fetched once
 * keeps returning fresh readings, as the robot's poll loop (or the simulator) refreshes them.
 */
public final class Sensor {
    private final RobotPort port;
    private final IrSensor position;

    Sensor(RobotPort port, IrSensor position) {
        this.port = port;
        this.position = position;
    }

    /**
     * @return the latest proximity reading, 0..1023: higher is nearer (about 1000 touching a wall,
     *     about 600 at 15–20 mm, a few tens beyond 50 mm)
     */
    public int getDistValue() {
        return port.proximity(position.index());
    }

    /** @return the latest ambient-light reading, 0..1023: lower is brighter (about 480 in the dark) */
    public int getLightValue() {
        return port.ambientLight(position.index());
    }

    /** @return this sensor's index, 0..7 */
    public int getIndex() {
        return position.index();
    }

    /** @return where this sensor sits on the robot and which way it looks */
    public IrSensor getPosition() {
        return position;
    }

    @Override
    public String toString() {
        return "Sensor " + position.index() + " (" + position + ")";
    }
}
