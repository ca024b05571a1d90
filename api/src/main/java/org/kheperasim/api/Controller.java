package org.kheperasim.api;

import org.kheperasim.api.spi.ControllerBinding;

/**
 * A friendlier base class for a first controller. Write {@link #doWork()}; it is called over and
 * over until the controller is asked to stop. No constructor is needed:
 * <pre>{@code
 * public class Avoider extends Controller {
 *     protected void doWork() {
 *         if (proximity(IrSensor.FRONT_LEFT) > 600) setSpeeds(-3, 3); else setSpeeds(5, 5);
 *         sleepMillis(100);
 *     }
 * }
 * }</pre>
 * It is still a {@link Thread} with the classic {@code (CurrentRobotState, MessagePasser)}
 * constructor available, so it runs wherever the Appendix-style controllers run.
 */
public abstract class Controller extends Thread {
    private final CurrentRobotState robot;
    private final MessagePasser messages;
    private final Sensor[] sensors;
    private volatile boolean active = true;
    /** How many times {@link #doWork()} has returned: tells a doWork() that returns at once from one that loops. */
    private volatile long rounds;

    /** For subclasses with no constructor: the backend that creates the controller binds it. */
    protected Controller() {
        this((CurrentRobotState) ControllerBinding.current().state(),
                (MessagePasser) ControllerBinding.current().messages());
    }

    /**
     * @param robot the robot's live state
     * @param messages where {@link #print(String)} sends text
     */
    protected Controller(CurrentRobotState robot, MessagePasser messages) {
        this.robot = robot;
        this.messages = messages;
        this.sensors = robot.getSensorValues();
        setName(getClass().getSimpleName());
    }

    /** Called once before the first {@link #doWork()}. Does nothing unless overridden. */
    protected void setup() {
    }

    /** One step of the controller: read sensors, set speeds, maybe sleep. Called repeatedly. */
    protected abstract void doWork();

    /**
     * Called once after the last {@link #doWork()} when the controller ends itself ({@link #killControl()}
     * from its own code). Stops the motors unless overridden. When the run ends or is stopped from outside,
     * the simulator stops the controller at its next robot call instead, and stops the motors itself: a
     * {@code cleanup()} that reads a sensor or prints then ends there.
     */
    protected void cleanup() {
        stopMotors();
    }

    @Override
    public final void run() {
        setup();
        while (active) {
            doWork();
            rounds++;
        }
        cleanup();
    }

    /** Ask the controller to stop after the current {@link #doWork()}. */
    public void killControl() {
        active = false;
    }

    /** @return true until the controller has been asked to stop */
    protected final boolean isActive() {
        return active;
    }

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

    /** @return all the robot's live sensors, in its index order (the Khepera's eight: 0..7) */
    protected final Sensor[] sensors() {
        return sensors;
    }

    /**
     * @param left left wheel speed, −127..127 units (≈ 8 mm/s each)
     * @param right right wheel speed, −127..127 units
     */
    protected final void setSpeeds(int left, int right) {
        robot.getMotorState().setMotorSpeeds(left, right);
    }

    /** Stop both wheels. */
    protected final void stopMotors() {
        robot.getMotorState().setMotorSpeeds(0, 0);
    }

    /** @return the left wheel position counter, pulses (≈ 0.08 mm) */
    protected final int leftPosition() {
        return robot.getMotorState().getLeftPosition();
    }

    /** @return the right wheel position counter, pulses (≈ 0.08 mm) */
    protected final int rightPosition() {
        return robot.getMotorState().getRightPosition();
    }

    /** @return the wheel motors */
    protected final Motor motor() {
        return robot.getMotorState();
    }

    /** @return the gripper turret */
    protected final Gripper gripper() {
        return robot.getGripper();
    }

    /** @return the K213 linear vision turret: 64 grey pixels across 36° ahead, pixel 0 on the left */
    protected final VisionTurret vision() {
        return robot.getVisionTurret();
    }

    /**
     * Lower the gripper arm to the floor and wait until it is there (about a second). Returns
     * early if the controller is asked to stop.
     */
    protected final void lowerArm() {
        gripper().lowerArm();
        awaitArm(ArmPosition.DOWN);
    }

    /** Raise the gripper arm and wait until it is up. Returns early if the controller is asked to stop. */
    protected final void raiseArm() {
        gripper().raiseArm();
        awaitArm(ArmPosition.UP);
    }

    /**
     * Close the fingers on whatever is between them and wait until they have closed.
     *
     * @return true when they hold something (the optical barrier between them is broken)
     */
    protected final boolean grab() {
        gripper().closeGripper();
        awaitFingers(GripperState.CLOSED);
        return gripper().isObjectPresent();
    }

    /** Open the fingers, letting go of what they hold, and wait until they are open. */
    protected final void release() {
        gripper().openGripper();
        awaitFingers(GripperState.OPEN);
    }

    /** @return true when something is between the fingers (the optical barrier is broken) */
    protected final boolean objectBetweenFingers() {
        return gripper().isObjectPresent();
    }

    /** How long the plain gripper verbs wait for the turret before giving up, ms of robot time. */
    private static final long TURRET_PATIENCE_MS = 10_000;
    private static final long TURRET_POLL_MS = 20;

    private void awaitArm(ArmPosition target) {
        Gripper g = gripper();
        awaitTurret(() -> g.getArmPosition() == target && !g.isArmMoving());
    }

    private void awaitFingers(GripperState target) {
        Gripper g = gripper();
        awaitTurret(() -> g.getGripperState() == target);
    }

    private void awaitTurret(java.util.function.BooleanSupplier done) {
        for (long waited = 0; active && waited < TURRET_PATIENCE_MS; waited += TURRET_POLL_MS) {
            if (done.getAsBoolean()) {
                return;
            }
            sleepMillis(TURRET_POLL_MS);
        }
    }

    /** @return the robot's live state */
    protected final CurrentRobotState robot() {
        return robot;
    }

    /**
     * Sleep for robot time; an interruption ends the sleep early and asks the controller to stop.
     *
     * @param millis milliseconds of robot time (simulated time in the simulator)
     */
    protected final void sleepMillis(long millis) {
        try {
            robot.port().sleep(millis);
        } catch (InterruptedException e) {
            active = false;
            Thread.currentThread().interrupt();
        }
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
