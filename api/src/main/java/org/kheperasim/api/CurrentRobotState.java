package org.kheperasim.api;

import org.kheperasim.api.spi.RobotPort;
import org.kheperasim.api.spi.RobotPorts;

/**
 * The controller's view of the robot: its sensors, motors and gripper. Every object it hands out
 * is a live view that keeps showing fresh values, so fetching them once at the start of
 * {@code run()} is enough.
 */
public final class CurrentRobotState {
    static {
        // Backends' controller styles (api.spi) reach the port through RobotPorts; students do not see it.
        RobotPorts.install(CurrentRobotState::port);
    }

    private final Sensor[] sensors;
    private final Motor motor;
    private final Gripper gripper;
    private final VisionTurret vision;
    private final RobotPort port;

    /** @param port the backend behind the view (backends construct this, students do not) */
    public CurrentRobotState(RobotPort port) {
        this.port = port;
        sensors = new Sensor[IrSensor.COUNT];
        for (IrSensor s : IrSensor.values()) {
            sensors[s.index()] = new Sensor(port, s);
        }
        motor = new Motor(port);
        gripper = new Gripper(port);
        vision = new VisionTurret(port);
    }

    /**
     * @return the eight IR sensors, indexed 0..7 in the robot's order (see {@link IrSensor}); a new
     *     array each call, holding the same live {@link Sensor} objects
     */
    public Sensor[] getSensorValues() {
        return sensors.clone();
    }

    /**
     * @param which a sensor position
     * @return that live sensor
     */
    public Sensor getSensor(IrSensor which) {
        return sensors[which.index()];
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
    RobotPort port() {
        return port;
    }
}
