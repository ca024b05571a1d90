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
 * then, on the controller's own thread, {@link #simStart()} (an override that sets speeds acts at
 * time 0) and {@link #run()}: {@code doWork()}, pause, {@code doWork()}, … until
 * {@link #setFinished setFinished(true)} (the user's Stop does the same), then {@code close()} once.
 *
 * <p>Units: speeds −9..9 per wheel, one Khepera speed unit (≈ 8 mm/s) each, a value outside
 * ignored; proximity 0..1023, higher = nearer; ambient light 0..1023, lower = brighter; wheel
 * positions in encoder pulses (≈ 0.08 mm), from 0 at the start of the run (or the original
 * simulator's counts, with the setting {@code wsu.positionUnits=legacy}); times in milliseconds of
 * robot time (simulated time in the simulator). The K213 vision turret of KSuite 1.1.2
 * ({@link #readLvtImage()}) and the later fork's pose ({@link #getRobotAngle()}) are here too.
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
    /** Robot time its constructor slept, ms: it passes when its thread starts (see {@link #sleep}). */
    private volatile long constructorSleep;

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
     * Start the controller's loop. The simulator and robot-link call this once, after
     * {@link #initialize} and before the first {@code doWork()}, on the controller's own thread, as
     * the original's loader did: an override that sets speeds ({@code super.simStart();
     * setMotorSpeeds(5, 5);}) takes effect at time 0. Calling {@code super.simStart()} from an
     * override, or {@code simStart()} again, starts no second loop. (The loop runs even if an
     * override leaves out {@code super.simStart()}; in the original it then never started.)
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
     * What the backend's thread runs: {@link #simStart()}, then the loop. An exception from
     * {@code simStart()} ends the controller as one from {@code doWork()} would: {@code close()} runs
     * and the exception leaves unchanged.
     */
    void runFromBackend() {
        try {
            long slept = constructorSleep;
            constructorSleep = 0;
            pause(slept);
            simStart();
        } catch (RuntimeException e) {
            closeAndRethrow(e);
            return;
        }
        run();
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
                robot().pauseLoop(waitTime);
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
     * swallowed. Called in the constructor, as the simulator or robot-link creates the controller
     * (course code did, as the original allowed it), it is a plain sleep too: the robot's clock runs
     * from the start of the run, so that time passes first, on the controller's thread before
     * {@link #simStart()}.
     *
     * @param ms milliseconds; 0 or less does not sleep
     */
    public void sleep(long ms) {
        CurrentRobotState s = state;
        if (s != null) {
            s.sleep(ms);
        } else if (ms > 0 && Boolean.TRUE.equals(BACKEND_CREATING.get())) {
            // In the constructor, as the simulator or robot-link creates it: the original slept there
            // plainly. The robot's clock starts with the run, so the time passes first thing on the
            // controller's own thread, before simStart().
            constructorSleep += ms;
        } else if (ms > 0) {
            plainSleep(ms);
        }
    }

    /** Not created by a backend, not connected: a plain sleep of the caller's thread, interruptions swallowed. */
    private static void plainSleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
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

    /**
     * @return the left wheel's position counter since the run started: encoder pulses (≈ 0.08 mm), or
     *     with the setting {@code wsu.positionUnits=legacy} the original simulator's counts (3 per degree
     *     of a turn on the spot)
     */
    public long getLeftWheelPosition() {
        return robot().getLeftPosition();
    }

    /**
     * @return the right wheel's position counter since the run started, in the units of {@link #getLeftWheelPosition()}
     */
    public long getRightWheelPosition() {
        return robot().getRightPosition();
    }

    // ------------------------------------------------------------------ KSuite 1.1.2: the K213 vision turret

    /**
     * Read the K213 linear vision turret (KSuite 1.1.2's API): one image of 64 pixels across the
     * turret's 36° field of view, index 0 the leftmost, each a grey level 0..255, higher = brighter (a
     * lamp 255, a ball bright, a wall dark). Reading takes the turret's reply over the serial link
     * (about 60 ms at 38400 baud), in the simulator and on the robot.
     *
     * @return a new array of 64 grey levels, 0.0..255.0
     */
    public float[] readLvtImage() {
        return robot().lvtImage();
    }

    /**
     * The brightest grey level the turret sees (KSuite 1.1.2's API): the greatest of the 64 pixels of
     * an image, as the original returned it (run, it gave 255.0 with a lamp in view, 230.0 with its
     * border brightest, 10.0 facing a wall); 0.0..255.0. It reads an image (about 60 ms at 38400 baud).
     * The index of the brightest pixel, which the turret itself can give ({@code T,2,O}), is the
     * student API's {@code vision().getBrightestPixel()}.
     *
     * @return a grey level, 0.0..255.0
     */
    public float getPixelMaxIntensity() {
        return robot().pixelMaxIntensity();
    }

    /**
     * The darkest grey level the turret sees (KSuite 1.1.2's API): the least of the 64 pixels of an
     * image, as the original returned it (10.0 with a wall in view); 0.0..255.0.
     *
     * @return a grey level, 0.0..255.0
     */
    public float getPixelMinIntensity() {
        return robot().pixelMinIntensity();
    }

    // ------------------------------------------------------------------ the later fork: the robot's pose

    /**
     * The robot's heading, as a later WSU fork's API gives it: radians in [0, 2π), growing clockwise on
     * the screen (y down), 0 facing east (+x). In the simulator the true heading; on a real robot its
     * odometry since the start (the console says so once).
     *
     * @return the heading, radians
     */
    public float getRobotAngle() {
        return robot().robotAngle();
    }

    /**
     * @return the robot centre's x in the original's 500 × 500 px panel (1 px = 2.4384 mm), from the
     *     left edge; in the simulator the true position, on a real robot its odometry since the start
     *     (from the original's start spot, 263 px)
     */
    public int getRobotXPosition() {
        return robot().robotX();
    }

    /**
     * @return the robot centre's y in the original's panel pixels, down from the top edge; in the
     *     simulator the true position, on a real robot its odometry since the start
     */
    public int getRobotYPosition() {
        return robot().robotY();
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
