package edu.wsu.KheperaSimulator;

/**
 * The base class of controllers written for the WSU Khepera Simulator. A subclass has a public
 * constructor without parameters and implements {@link #doWork()} and {@link #close()}:
 * <pre>{@code
 * import edu.wsu.KheperaSimulator.RobotController;
 *
 * public class Avoider extends RobotController {
 *     public Avoider() { }
 *     public void doWork() throws Exception {
 *         if (getDistanceValue(2) > 600 || getDistanceValue(3) > 600) setMotorSpeeds(3, -3);
 *         else setMotorSpeeds(5, 5);
 *     }
 *     public void close() throws Exception { setMotorSpeeds(0, 0); }
 * }
 * }</pre>
 * The simulator (or robot-link) constructs it, calls {@link #initialize} with a pause of 20 ms,
 * and runs {@link #run()} on the controller's own thread: {@code doWork()}, pause, {@code doWork()},
 * … until {@link #setFinished setFinished(true)} (the user's Stop does the same), then
 * {@code close()} once.
 *
 * <p>Units: speeds −9..9 per wheel, one Khepera speed unit (≈ 8 mm/s) each, a value outside
 * ignored; proximity 0..1023, higher = nearer; ambient light 0..1023, lower = brighter; wheel
 * positions in encoder pulses (≈ 0.08 mm), from 0 at the start of the run; times in milliseconds of
 * robot time (simulated time in the simulator).
 *
 * <p>An exception from {@code doWork()} ends the loop; {@code close()} still runs, the wheels are
 * stopped, and the exception leaves {@code run()} unchanged for the simulator to report. The
 * application keeps running.
 */
public abstract class RobotController implements Controller {
    /** The pause between {@code doWork()} calls that the simulator sets in {@link #initialize}, ms. */
    static final long SIMULATOR_WAIT_MS = 20;

    private volatile String name;
    private volatile CurrentRobotState state;
    private volatile long waitTime = SIMULATOR_WAIT_MS;
    private volatile boolean finished;
    private volatile boolean running;
    private volatile Thread thread;

    /** Does nothing: the simulator connects the controller to the robot in {@link #initialize}. */
    public RobotController() {
    }

    /**
     * Called by the simulator after construction: connects the controller to the robot and sets
     * the pause between {@code doWork()} calls (the simulator passes 20 ms, overriding a
     * {@code setWaitTime} made in the constructor, as the original did).
     *
     * @param name the controller's name (its class's simple name)
     * @param state the robot
     * @param waitMs pause between {@code doWork()} calls, ms of robot time
     */
    protected void initialize(String name, CurrentRobotState state, long waitMs) {
        this.name = name;
        this.state = state;
        this.waitTime = waitMs;
    }

    /**
     * Start the controller's thread, when it has not started yet. The simulator and robot-link start
     * it themselves; a controller never needs to call this.
     */
    protected void simStart() {
        if (Boolean.TRUE.equals(BACKEND_CREATING.get())) {
            // Called from the constructor while a backend creates the controller: it attaches and
            // starts its own runner next.
            return;
        }
        Thread t;
        synchronized (this) {
            if (thread != null) {
                // The runner attached by the simulator or robot-link (which start it themselves), or
                // the thread an earlier simStart() made and started.
                return;
            }
            t = new Thread(this, name != null ? name : getClass().getSimpleName());
            thread = t;
        }
        t.start();
    }

    /** @param ms pause between successive {@code doWork()} calls, ms of robot time; 0 or less: none */
    protected void setWaitTime(long ms) {
        waitTime = ms;
    }

    /**
     * @param f true: the loop ends after the current {@code doWork()} and its pause, then
     *     {@code close()} runs once; false: it goes on
     */
    protected void setFinished(boolean f) {
        finished = f;
    }

    /** @return true while the {@code doWork()} loop runs */
    protected boolean isRunning() {
        return running;
    }

    /**
     * The loop: {@code doWork()}, pause, until finished; then {@code close()} once. An exception from
     * {@code doWork()} ends the loop, {@code close()} still runs (its own exception is attached to the
     * first as suppressed), and the exception is rethrown unchanged.
     */
    @Override
    public void run() {
        running = true;
        try {
            while (!finished) {
                doWork();
                pause(waitTime);
            }
        } catch (Exception e) {
            running = false;
            if (finished && e instanceof InterruptedException) {
                // Stopped while sleeping in doWork: a stop, not a failure.
                closeAndRethrow(null);
                return;
            }
            closeAndRethrow(e);
        } finally {
            running = false;
        }
        closeAndRethrow(null);
    }

    private void closeAndRethrow(Exception failure) {
        try {
            close();
        } catch (Exception e) {
            if (failure == null) {
                throw rethrow(e);
            }
            failure.addSuppressed(e);
        }
        if (failure != null) {
            throw rethrow(failure);
        }
    }

    /**
     * Throws any exception without wrapping it: doWork() and close() may throw checked exceptions,
     * which run() cannot declare; wrapping would hide the controller's own stack trace.
     */
    @SuppressWarnings("unchecked")
    private static <T extends Throwable> RuntimeException rethrow(Throwable t) throws T {
        throw (T) t;
    }

    /**
     * Sleep for robot time (simulated time in the simulator). An interruption ends it early and is
     * swallowed.
     *
     * @param ms milliseconds; 0 or less does not sleep
     */
    public void sleep(long ms) {
        robot().sleep(ms);
    }

    private void pause(long ms) {
        robot().sleep(ms);
    }

    /**
     * Set both wheel speeds. A speed outside −9..9 is ignored and that wheel keeps its speed.
     *
     * @param left left wheel, −9..9 (one Khepera speed unit, ≈ 8 mm/s, each); positive drives forward
     * @param right right wheel, −9..9
     */
    public void setMotorSpeeds(int left, int right) {
        robot().setMotorSpeeds(left, right);
    }

    /** @param speed left wheel, −9..9 (≈ 8 mm/s each); a value outside is ignored */
    public void setLeftMotorSpeed(int speed) {
        robot().setLeftMotorSpeed(speed);
    }

    /** @param speed right wheel, −9..9 (≈ 8 mm/s each); a value outside is ignored */
    public void setRightMotorSpeed(int speed) {
        robot().setRightMotorSpeed(speed);
    }

    /**
     * Raise or lower the gripper's arm.
     *
     * @param state {@link KSGripperStates#ARM_UP} or {@link KSGripperStates#ARM_DOWN}; other values are ignored
     */
    public void setArmState(int state) {
        robot().arm(state);
    }

    /**
     * Open or close the fingers.
     *
     * @param state {@link KSGripperStates#GRIP_OPEN} or {@link KSGripperStates#GRIP_CLOSED}; other values are ignored
     */
    public void setGripperState(int state) {
        robot().gripper(state);
    }

    /**
     * @return {@link KSGripperStates#ARM_UP} (at the start) or {@link KSGripperStates#ARM_DOWN}: where
     *     the arm last came to rest; while it travels, where it left
     */
    public int getArmState() {
        return robot().arm();
    }

    /** @return {@link KSGripperStates#GRIP_OPEN} (at the start) or {@link KSGripperStates#GRIP_CLOSED} */
    public int getGripperState() {
        return robot().gripper();
    }

    /** @return true when something breaks the light barrier between the fingers */
    public boolean isObjectPresent() {
        return robot().objectPresent();
    }

    /** @return true when the fingers are closed on an object */
    public boolean isObjectHeld() {
        return robot().objectHeld();
    }

    /**
     * @param i sensor 0..7 (0 left, 1 left 45°, 2 front left, 3 front right, 4 right 45°, 5 right,
     *     6 rear right, 7 rear left)
     * @return ambient light, 0..1023, lower = brighter: about 500 in the dark
     * @throws ArrayIndexOutOfBoundsException when {@code i} is not 0..7
     */
    public int getLightValue(int i) {
        return robot().light(i);
    }

    /**
     * @param i sensor 0..7, in the order of {@link #getLightValue}
     * @return proximity, 0..1023, higher = nearer: a few units when nothing is seen, about 1000 at contact
     * @throws ArrayIndexOutOfBoundsException when {@code i} is not 0..7
     */
    public int getDistanceValue(int i) {
        return robot().distance(i);
    }

    /**
     * @return resistivity of what the fingers hold, 0..255; 0 when they hold nothing (the original
     *     simulator always returned 0; this one measures, as the real turret does)
     */
    public int getResistivity() {
        return robot().resistivity();
    }

    /** @return the left wheel's position counter, encoder pulses (≈ 0.08 mm) since the run started */
    public long getLeftWheelPosition() {
        return robot().getLeftPosition();
    }

    /** @return the right wheel's position counter, encoder pulses (≈ 0.08 mm) since the run started */
    public long getRightWheelPosition() {
        return robot().getRightPosition();
    }

    // ------------------------------------------------------------------ for the runner

    /** True on a backend's thread while it runs a controller's constructor (see {@link WsuControllerStyle}). */
    static final ThreadLocal<Boolean> BACKEND_CREATING = new ThreadLocal<>();

    /** The runner thread that drives this controller, so that {@link #simStart()} does not start another. */
    synchronized void attach(Thread runner) {
        thread = runner;
    }

    /** The robot, once {@link #initialize} has connected it. */
    CurrentRobotState robot() {
        CurrentRobotState s = state;
        if (s == null) {
            throw new IllegalStateException(getClass().getName() + " is not connected to a robot yet: the"
                    + " simulator connects it after the constructor has run, so use the robot in doWork() (or"
                    + " close()), not in the constructor");
        }
        return s;
    }
}
