package org.kheperasim.api.spi;

import java.util.Map;
import java.util.Optional;

/**
 * What a backend (the simulator, or the link to a real robot) provides behind the student API.
 * Students never see this interface; {@link org.kheperasim.api.CurrentRobotState} and its
 * {@code Sensor}, {@code Motor} and {@code Gripper} objects delegate every call to it, which is
 * what makes them live views.
 *
 * <p>Every method may be called from the controller's thread. A simulator implementation charges
 * simulated time for each call (that is how a busy loop makes time pass); a robot implementation
 * reads values its poll loop keeps fresh. Units are those of the {@code org.kheperasim.api}
 * package documentation.
 */
public interface RobotPort {

    /**
     * @param index the sensor, 0..7 ({@link org.kheperasim.api.IrSensor#index()})
     * @return proximity of sensor {@code index}, 0..1023 on a Khepera ({@link #maxProximity()}), higher = nearer
     */
    int proximity(int index);

    /**
     * @param index the sensor, 0..7 ({@link org.kheperasim.api.IrSensor#index()})
     * @return ambient light at sensor {@code index}, 0..1023, lower = brighter
     */
    int ambientLight(int index);

    /**
     * Ask for wheel speeds, in speed units (≈ 8 mm/s), each already checked to lie in −127..127.
     *
     * @param left left wheel, speed units
     * @param right right wheel, speed units
     */
    void setSpeeds(int left, int right);

    /** @return the speed last asked for on the left wheel, speed units */
    int leftSpeed();

    /** @return the speed last asked for on the right wheel, speed units */
    int rightSpeed();

    /** @return left wheel position counter, pulses (≈ 0.08 mm) */
    int leftPosition();

    /** @return right wheel position counter, pulses (≈ 0.08 mm) */
    int rightPosition();

    /**
     * Set both wheel position counters, pulses (the protocol's {@code G} command).
     *
     * @param left left counter, pulses (≈ 0.08 mm)
     * @param right right counter, pulses
     */
    void setPositions(int left, int right);

    /**
     * Move the gripper arm down or up.
     *
     * @param down true for down (to pick up), false for up
     */
    void setArmDown(boolean down);

    /** @return true when the arm last came to rest down, false when up */
    boolean armDown();

    /** @return true while the arm is travelling between positions */
    boolean armMoving();

    /**
     * Close or open the fingers.
     *
     * @param closed true to close them, false to open them
     */
    void setFingersClosed(boolean closed);

    /** @return true when the fingers are closed (or closing), false when open */
    boolean fingersClosed();

    /** @return true when something breaks the optical barrier between the fingers */
    boolean objectPresent();

    /** @return resistivity of what the fingers hold, 0..255; 0 with nothing held */
    int resistivity();

    /**
     * Sleep for robot time: simulated time in the simulator, wall time on the robot. Used by
     * {@link org.kheperasim.api.Controller#sleepMillis}; a student's own {@code Thread.sleep} is
     * put on the simulation clock by the simulator's class loader instead.
     *
     * @param millis milliseconds of robot time
     * @throws InterruptedException if the controller thread is interrupted while sleeping
     */
    void sleep(long millis) throws InterruptedException;

    /**
     * The pause a controller's own loop takes between two of its steps (a WSU {@code RobotController}'s
     * wait between {@code doWork()} calls): by default a {@link #sleep} of exactly that long. A backend
     * may lengthen it as the machine the original simulator ran on did (the simulator's
     * {@code wsu.loopTiming=desktop}).
     *
     * @param millis milliseconds of robot time the loop asks to wait
     * @throws InterruptedException if the controller thread is interrupted while waiting
     */
    default void pauseLoop(long millis) throws InterruptedException {
        sleep(millis);
    }

    /**
     * Deliver a line of text from the controller to the person watching (console, log).
     *
     * @param text the line, without a line end
     */
    void message(String text);

    /**
     * Take an image with the K213 linear vision turret (its {@code T,2,N} command): 64 pixels, 0 the
     * leftmost of its 36° field of view, each a grey level 0..255 (higher = brighter). On the robot
     * and in a tethered simulation the call waits for the turret's reply on the serial line.
     *
     * @return a new array of {@link org.kheperasim.api.VisionTurret#PIXELS} grey levels, 0..255
     * @throws UnsupportedOperationException when this backend has no vision turret
     */
    default int[] visionImage() {
        throw new UnsupportedOperationException("this robot has no K213 vision turret");
    }

    /**
     * @return the index, 0..63, of the turret's brightest pixel (its {@code T,2,O} command; the
     *     leftmost of equals)
     * @throws UnsupportedOperationException when this backend has no vision turret
     */
    default int visionBrightest() {
        throw new UnsupportedOperationException("this robot has no K213 vision turret");
    }

    /**
     * @return the index, 0..63, of the turret's darkest pixel (its {@code T,2,P} command; the
     *     leftmost of equals)
     * @throws UnsupportedOperationException when this backend has no vision turret
     */
    default int visionDarkest() {
        throw new UnsupportedOperationException("this robot has no K213 vision turret");
    }

    /**
     * @return where the robot truly is, when the backend knows (the simulator); empty on a real
     *     robot, whose pose only its odometry can estimate
     */
    default Optional<TruePose> truePose() {
        return Optional.empty();
    }

    /**
     * A backend's setting that a controller style may consult (the WSU API's {@code wsu.positionUnits},
     * say): the simulator's settings, robot-link's options.
     *
     * @param key the setting's name
     * @return its value, or null when the backend does not know it
     */
    default String option(String key) {
        return null;
    }

    /**
     * @return the numbers the run hands the controller, by name (the student API shows them as
     *     {@code Parameters}); none by default
     */
    default Map<String, double[]> parameters() {
        return Map.of();
    }

    /** @return the robot's name ({@code khepera1}, {@code epuck}); by default the Khepera I */
    default String robotName() {
        return "khepera1";
    }

    /** @return how many infrared sensors the robot has; by default the Khepera's eight */
    default int sensorCount() {
        return 8;
    }

    /**
     * @param index a sensor, 0 to {@link #sensorCount()} - 1
     * @return where it sits and which way it looks (a Khepera-only backend gives the student API's
     *     {@code IrSensor} poses)
     */
    Mount mount(int index);

    /** @return the largest speed magnitude the robot accepts, its speed units; by default the Khepera's 127 */
    default int maxSpeed() {
        return 127;
    }

    /** @return the wheel speed of one speed unit, mm/s; by default the Khepera's 8 */
    default double mmPerSecondPerUnit() {
        return 8;
    }

    /**
     * @return the largest proximity reading the robot's sensors give, counts, noise aside: its response's
     *     peak plus offset within its scale ({@code max_reading}); by default the Khepera's 1023 (the
     *     bundled e-puck's: 2976 of its 12-bit 4095)
     */
    default int maxProximity() {
        return 1023;
    }
}
