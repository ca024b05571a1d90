package edu.wsu.KheperaSimulator;

import org.kheperasim.api.spi.RobotPort;

/**
 * The robot as a WSU controller sees it, drawn from the backend's {@link RobotPort}: the
 * simulated robot, or a real Khepera over its serial link. {@link RobotController}'s methods
 * delegate here. Only the motor and wheel-position methods are public, as in the original; the
 * rest is for {@code RobotController}.
 *
 * <p>Speeds are WSU units, −9..9, one Khepera speed unit (about 8 mm/s) each; a value outside
 * −9..9 is ignored and that wheel keeps its speed. Wheel positions are encoder pulses (about
 * 0.08 mm each), 0 at the start of the run; with the backend's option {@code wsu.positionUnits=legacy}
 * they count as the original simulator's counter did (3 counts per degree of a turn on the spot).
 *
 * <p>A state made with the public constructor is not connected to a robot: it remembers the speeds
 * it is given and reports wheel positions of 0.
 */
public class CurrentRobotState {
    /** The backend behind this state; null when not connected to a robot. */
    private final RobotPort port;
    private final Odometer left = new Odometer();
    private final Odometer right = new Odometer();
    private final WsuPose pose;
    /** Wheel positions count as the original simulator's counter did (the backend's {@code wsu.positionUnits}). */
    private final boolean legacyPositions;
    /** Speeds are as fast as the original simulator drew them (the backend's {@code wsu.speedUnits}). */
    private final boolean legacySpeeds;
    /** The speeds last accepted, WSU units. */
    private int leftSpeed;
    private int rightSpeed;

    /** A state connected to no robot (the backends connect the one a controller gets). */
    public CurrentRobotState() {
        this(null);
    }

    /** @param port the backend, or null for a state connected to no robot */
    CurrentRobotState(RobotPort port) {
        this.port = port;
        this.pose = port == null ? null : new WsuPose(port);
        this.legacyPositions = port != null && WsuUnits.legacyPositions(port.option(WsuUnits.POSITION_UNITS));
        this.legacySpeeds = port != null && WsuUnits.legacySpeeds(port.option(WsuUnits.SPEED_UNITS));
    }

    /**
     * Set both wheel speeds. A speed outside −9..9 is ignored, and that wheel keeps its speed (the
     * original's rule); when both are outside, nothing is sent.
     *
     * @param left left wheel, −9..9 WSU units (one Khepera speed unit, ≈ 8 mm/s, each, or ≈ 30 mm/s with the
     *     backend's {@code wsu.speedUnits=legacy}); positive drives forward
     * @param right right wheel, −9..9 WSU units
     */
    public void setMotorSpeeds(int left, int right) {
        boolean leftOk = WsuUnits.validSpeed(left);
        boolean rightOk = WsuUnits.validSpeed(right);
        if (!leftOk && !rightOk) {
            return;
        }
        int l;
        int r;
        synchronized (this) {
            if (leftOk) {
                leftSpeed = left;
            }
            if (rightOk) {
                rightSpeed = right;
            }
            l = leftSpeed;
            r = rightSpeed;
        }
        // The robot is told outside the lock: in the simulator the call may give the turn to the
        // controller's other threads, which must not find the lock taken.
        if (port != null) {
            port.setSpeeds(WsuUnits.toKheperaSpeed(l, legacySpeeds), WsuUnits.toKheperaSpeed(r, legacySpeeds));
        }
    }

    /**
     * Set the left wheel's speed; the right wheel keeps its speed.
     *
     * @param speed −9..9 WSU units (≈ 8 mm/s each); a value outside is ignored
     */
    public void setLeftMotorSpeed(int speed) {
        if (WsuUnits.validSpeed(speed)) {
            setMotorSpeeds(speed, WsuUnits.INVALID_SPEED);
        }
    }

    /**
     * Set the right wheel's speed; the left wheel keeps its speed.
     *
     * @param speed −9..9 WSU units (≈ 8 mm/s each); a value outside is ignored
     */
    public void setRightMotorSpeed(int speed) {
        if (WsuUnits.validSpeed(speed)) {
            setMotorSpeeds(WsuUnits.INVALID_SPEED, speed);
        }
    }

    /**
     * @return the left wheel's position counter since the run started: encoder pulses (≈ 0.08 mm
     *     each), or with the backend's {@code wsu.positionUnits=legacy} the original simulator's counts
     *     (3 per degree of a turn on the spot); it grows driving forward and stands still while the
     *     robot is blocked
     */
    public long getLeftPosition() {
        return port == null ? 0 : inUnits(left.read(port.leftPosition()));
    }

    /** @return the right wheel's position counter since the run started, in the units of {@link #getLeftPosition()} */
    public long getRightPosition() {
        return port == null ? 0 : inUnits(right.read(port.rightPosition()));
    }

    private long inUnits(long pulses) {
        return legacyPositions ? StrictMath.round(pulses * WsuUnits.LEGACY_COUNTS_PER_PULSE) : pulses;
    }

    // ------------------------------------------------------------------ for RobotController

    /** The run starts now: wheel positions count from here, and the wheels stand still. */
    void startRun() {
        RobotPort p = connected();
        int l = p.leftPosition();
        int r = p.rightPosition();
        left.zero(l);
        right.zero(r);
        pose.start(l, r);
        synchronized (this) {
            leftSpeed = 0;
            rightSpeed = 0;
        }
    }

    /** Stop both wheels, whatever happens (the controller is ending, perhaps because it is being stopped). */
    void stopQuietly() {
        if (port == null) {
            return;
        }
        try {
            synchronized (this) {
                leftSpeed = 0;
                rightSpeed = 0;
            }
            port.setSpeeds(0, 0);
        } catch (RuntimeException | Error e) {
            // A backend that is stopping the controller refuses further calls; it stops the robot itself.
        }
    }

    /** @return the left wheel's speed last accepted, WSU units */
    synchronized int leftSpeed() {
        return leftSpeed;
    }

    /** @return the right wheel's speed last accepted, WSU units */
    synchronized int rightSpeed() {
        return rightSpeed;
    }

    /** @param index 0..7 @return proximity, 0..1023, higher = nearer */
    int distance(int index) {
        return connected().proximity(sensor(index));
    }

    /** @param index 0..7 @return ambient light, 0..1023, lower = brighter (about 500 in the dark) */
    int light(int index) {
        return connected().ambientLight(sensor(index));
    }

    /** @param state {@link KSGripperStates#ARM_UP} or {@link KSGripperStates#ARM_DOWN}; others ignored */
    void arm(int state) {
        if (state == KSGripperStates.ARM_UP) {
            connected().setArmDown(false);
        } else if (state == KSGripperStates.ARM_DOWN) {
            connected().setArmDown(true);
        }
    }

    /** @return where the arm last came to rest (while it travels, where it left) */
    int arm() {
        return connected().armDown() ? KSGripperStates.ARM_DOWN : KSGripperStates.ARM_UP;
    }

    /** @param state {@link KSGripperStates#GRIP_OPEN} or {@link KSGripperStates#GRIP_CLOSED}; others ignored */
    void gripper(int state) {
        if (state == KSGripperStates.GRIP_OPEN) {
            connected().setFingersClosed(false);
        } else if (state == KSGripperStates.GRIP_CLOSED) {
            connected().setFingersClosed(true);
        }
    }

    /** @return the fingers' state */
    int gripper() {
        return connected().fingersClosed() ? KSGripperStates.GRIP_CLOSED : KSGripperStates.GRIP_OPEN;
    }

    /** @return whether something breaks the light barrier between the fingers */
    boolean objectPresent() {
        return connected().objectPresent();
    }

    /** @return whether the fingers are closed on something (closed, and the barrier broken) */
    boolean objectHeld() {
        RobotPort p = connected();
        return p.fingersClosed() && p.objectPresent();
    }

    /** @return resistivity of what the fingers hold, 0..255 */
    int resistivity() {
        return connected().resistivity();
    }

    /**
     * @return a new image of the K213 vision turret as KSuite 1.1.2 returned it: 64 floats, the grey
     *     levels 0..255 (higher = brighter), index 0 the leftmost pixel
     */
    float[] lvtImage() {
        int[] grey = connected().visionImage();
        float[] out = new float[grey.length];
        for (int i = 0; i < grey.length; i++) {
            out[i] = grey[i];
        }
        return out;
    }

    /**
     * @return the greatest grey level of a new image (KSuite 1.1.2's {@code getPixelMaxIntensity()}, as
     *     the original returned it: 255.0 with a lamp in view); one image read ({@code T,2,N} on the robot)
     */
    float pixelMaxIntensity() {
        int max = 0;
        for (int v : connected().visionImage()) {
            max = Math.max(max, v);
        }
        return max;
    }

    /** @return the least grey level of a new image (KSuite 1.1.2's {@code getPixelMinIntensity()}) */
    float pixelMinIntensity() {
        int min = 255;
        for (int v : connected().visionImage()) {
            min = Math.min(min, v);
        }
        return min;
    }

    /** @return the heading, radians in [0, 2π), growing clockwise on the screen, 0 facing east */
    float robotAngle() {
        connected();
        return pose.angle();
    }

    /** @return the centre's x, the original's panel pixels from the left */
    int robotX() {
        connected();
        return pose.x();
    }

    /** @return the centre's y, the original's panel pixels down from the top */
    int robotY() {
        connected();
        return pose.y();
    }

    /**
     * Sleep for robot time (simulated time in the simulator, wall time on the robot). An
     * interruption ends the sleep early and is swallowed, as in the original.
     *
     * @param millis milliseconds; 0 or less does not sleep
     */
    void sleep(long millis) {
        if (millis <= 0) {
            return;
        }
        try {
            connected().sleep(millis);
        } catch (InterruptedException e) {
            // The original swallowed interruptions; a halt is signalled by setFinished instead.
        }
    }

    /**
     * The pause between two {@code doWork()} calls: a sleep of robot time, which the simulator may
     * lengthen as the original's desktop did ({@link RobotPort#pauseLoop}).
     *
     * @param millis milliseconds; 0 or less does not wait
     */
    void pauseLoop(long millis) {
        if (millis <= 0) {
            return;
        }
        try {
            connected().pauseLoop(millis);
        } catch (InterruptedException e) {
            // Swallowed as in sleep(): a halt is signalled by setFinished instead.
        }
    }

    private RobotPort connected() {
        if (port == null) {
            throw new IllegalStateException("this CurrentRobotState is not connected to a robot: the simulator"
                    + " or robot-link connects the one it gives a RobotController; read the robot from doWork(),"
                    + " not from the constructor");
        }
        return port;
    }

    private static int sensor(int index) {
        if (index < 0 || index > 7) {
            throw new ArrayIndexOutOfBoundsException("sensor " + index + " does not exist: the Khepera's sensors"
                    + " are numbered 0..7 (0 left, 1 left 45°, 2 front left, 3 front right, 4 right 45°, 5 right,"
                    + " 6 rear right, 7 rear left)");
        }
        return index;
    }

    /**
     * A wheel's counter as a {@code long} from 0 at the run's start: the robot's 32-bit counter is
     * followed by its differences, so it never wraps.
     */
    private static final class Odometer {
        private boolean zeroed;
        private int last;
        private long total;

        synchronized void zero(int raw) {
            zeroed = true;
            last = raw;
            total = 0;
        }

        synchronized long read(int raw) {
            if (!zeroed) {
                zero(raw);
            }
            total += raw - last; // int subtraction: right across the counter's wrap-around
            last = raw;
            return total;
        }
    }
}
