package org.kheperasim.api;

import org.kheperasim.api.spi.Mount;
import org.kheperasim.api.spi.RobotPort;
import org.kheperasim.api.spi.RobotPorts;

/**
 * The controller's view of the robot: its sensors, motors and gripper. Every object it hands out
 * is a live view that keeps showing fresh values, so fetching them once at the start of
 * {@code run()} is enough.
 */
public final class CurrentRobotState {
    static {
        // Backends' controller styles (api.binding) reach the port through RobotPorts; students do not see it.
        RobotPorts.install(CurrentRobotState.class, CurrentRobotState::port);
    }

    private final Sensor[] sensors;
    private final Motor motor;
    private final Gripper gripper;
    private final VisionTurret vision;
    private final RobotPort port;
    private volatile Parameters parameters;

    /** @param port the backend behind the view (backends construct this, students do not) */
    public CurrentRobotState(RobotPort port) {
        this.port = port;
        sensors = new Sensor[port.sensorCount()];
        for (int i = 0; i < sensors.length; i++) {
            Mount m = port.mount(i);
            sensors[i] = new Sensor(port, new SensorMount(i, m.name(), m.xMm(), m.yMm(), m.headingDeg()));
        }
        motor = new Motor(port);
        gripper = new Gripper(port);
        vision = new VisionTurret(port);
    }

    /**
     * @return the robot's IR sensors in its order (the Khepera's eight: see {@link IrSensor}); a new
     *     array each call, holding the same live {@link Sensor} objects
     */
    public Sensor[] getSensorValues() {
        return sensors.clone();
    }

    /**
     * @param which a sensor position: the Khepera's names, which on another robot name the sensor of
     *     that index (the bundled robots list theirs in the Khepera's order)
     * @return that live sensor
     * @throws IllegalArgumentException naming the robot when it has no sensor of that index
     */
    public Sensor getSensor(IrSensor which) {
        return getSensor(which.index());
    }

    /**
     * @param index a sensor index, 0 to the robot's sensor count - 1
     * @return that live sensor
     * @throws IllegalArgumentException naming the robot and its sensors when there is none of that index
     */
    public Sensor getSensor(int index) {
        if (index < 0 || index >= sensors.length) {
            throw new IllegalArgumentException("sensor " + index
                    + (index >= 0 && index < IrSensor.COUNT ? " (" + IrSensor.of(index) + ")" : "")
                    + " does not exist: this robot (" + port.robotName() + ") has " + sensors.length + " sensors, 0.."
                    + (sensors.length - 1)
                    + "; the controller was written for another robot (see docs/robot-files.md)");
        }
        return sensors[index];
    }

    /** @return the robot's name ({@code khepera1}, {@code epuck}, or a robot file's) */
    public String getRobotName() {
        return port.robotName();
    }

    /** @return the wheel motors and position counters */
    public Motor getMotorState() {
        return motor;
    }

    /** @return the gripper turret */
    public Gripper getGripper() {
        return gripper;
    }

    /** @return the K213 linear vision turret (a one-dimensional camera looking ahead) */
    public VisionTurret getVisionTurret() {
        return vision;
    }

    /** The backend behind this view, for {@link Controller}'s helpers. */
    /** @return the numbers the run hands the controller (see {@link Controller#parameters()}), read once */
    Parameters parameters() {
        // A controller may ask every step; the run's numbers are fixed before it is made.
        Parameters p = parameters;
        if (p == null) {
            p = Parameters.of(port.parameters());
            parameters = p;
        }
        return p;
    }

    RobotPort port() {
        return port;
    }
}
