package org.kheperasim.api;

import org.kheperasim.api.spi.ControllerBinding;

/**
 * A controller the backend calls once per control period, instead of one that runs in a thread of
 * its own: the style of Enki's, ARGoS's and Webots' step loops, for swarms. Read the sensors, set
 * the motors and return; never sleep. It sees the same sensor, motor and gripper objects as a
 * {@link Controller}, with the same serial-link timing: each call costs its time, and the next step
 * comes one period after this one's last call (so a {@code step()} and a {@link Controller}'s
 * {@code doWork()} that ends with {@code sleepMillis(period)} drive the robot the same way).
 *
 * <pre>{@code
 * public class Avoid extends StepController {
 *     protected void step() {
 *         boolean blocked = proximity(IrSensor.FRONT_LEFT) > 500 || proximity(IrSensor.FRONT_RIGHT) > 500;
 *         setSpeeds(blocked ? 4 : 6, blocked ? -4 : 6);
 *     }
 * }
 * }</pre>
 *
 * <p>The simulator runs every step inline, on no thread of the controller's, which is what makes a
 * thousand robots fast; robot-link runs the same class on the real robot in a thread that steps it
 * every period.
 */
public abstract class StepController {
    private final CurrentRobotState robot;
    private final MessagePasser messages;
    private final Sensor[] sensors;

    /** For subclasses with no constructor: the backend that creates the controller binds it. */
    protected StepController() {
        this((CurrentRobotState) ControllerBinding.current().state(),
                (MessagePasser) ControllerBinding.current().messages());
    }

    /**
     * @param robot the robot's live state
     * @param messages where {@link #print(String)} sends text
     */
    protected StepController(CurrentRobotState robot, MessagePasser messages) {
        this.robot = robot;
        this.messages = messages;
        this.sensors = robot.getSensorValues();
    }

    /** Called once before the first {@link #step()}. Does nothing unless overridden. */
    protected void setup() {
    }

    /** One control period's decision: read sensors, set speeds, return. Never sleep here. */
    protected abstract void step();

    /**
     * Called after the last {@link #step()} by a backend that ends the controller itself (robot-link,
     * when its run ends). Stops the motors unless overridden. The simulator does not call it: at the
     * end of a run it stops the robot where it is.
     */
    protected void cleanup() {
        stopMotors();
    }

    /** @return the control period, ms of robot time: the time from one step's end to the next step (default 100) */
    protected long periodMillis() {
        return 100;
    }

    // ------------------------------------------------------------------ called by the backend

    /** Called by the backend before the first step; calls {@link #setup()}. */
    public final void begin() {
        setup();
    }

    /** Called by the backend once per period; calls {@link #step()}. */
    public final void stepOnce() {
        step();
    }

    /** Called by the backend after the last step; calls {@link #cleanup()}. */
    public final void end() {
        cleanup();
    }

    /** @return the control period the backend keeps, ms, at least 1 */
    public final long period() {
        return StrictMath.max(1, periodMillis());
    }

    // ------------------------------------------------------------------ the robot

    /**
     * @param sensor which sensor
     * @return proximity at that sensor, 0..1023, higher = nearer
     */
    protected final int proximity(IrSensor sensor) {
        return sensor(sensor).getDistValue();
    }

    /**
     * @param sensor which sensor
     * @return ambient light at that sensor, 0..1023, lower = brighter
     */
    protected final int light(IrSensor sensor) {
        return sensor(sensor).getLightValue();
    }

    /** @return the live sensor of that index; a robot without it refuses, naming itself and its sensors */
    private Sensor sensor(IrSensor sensor) {
        int i = sensor.index();
        return i < sensors.length ? sensors[i] : robot.getSensor(sensor);
    }

    /** @return the robot's sensors, live, in its order (the Khepera's eight: see {@link IrSensor}) */
    protected final Sensor[] sensors() {
        return sensors;
    }

    /**
     * @param left left wheel, units of 8 mm/s
     * @param right right wheel, units of 8 mm/s
     */
    protected final void setSpeeds(int left, int right) {
        robot.getMotorState().setMotorSpeeds(left, right);
    }

    /** Stop both wheels. */
    protected final void stopMotors() {
        setSpeeds(0, 0);
    }

    /** @return the left wheel's position counter, pulses of 0.08 mm */
    protected final int leftPosition() {
        return robot.getMotorState().getLeftPosition();
    }

    /** @return the right wheel's position counter, pulses of 0.08 mm */
    protected final int rightPosition() {
        return robot.getMotorState().getRightPosition();
    }

    /** @return the robot's live state */
    protected final CurrentRobotState robot() {
        return robot;
    }

    /** @param text one line to show on the console */
    protected final void print(String text) {
        messages.sendMessage(text);
    }

    /**
     * @return the numbers the run hands this controller (a weight vector, a genome: see {@link Parameters}); none
     *     unless the run was given some ({@code khepera-sim evaluate}'s jobs,
     *     {@code Simulation.builder().parameters(...)})
     */
    protected final Parameters parameters() {
        return robot.parameters();
    }
}
