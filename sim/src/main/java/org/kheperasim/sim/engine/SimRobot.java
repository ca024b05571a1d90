package org.kheperasim.sim.engine;

import java.util.BitSet;
import java.util.List;
import java.util.SplittableRandom;
import org.kheperasim.api.ArmPosition;
import org.kheperasim.api.GripperState;
import org.kheperasim.api.IrSensor;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.link.timing.PollStep;
import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.RayHit;
import org.kheperasim.sim.arena.Region;

/**
 * One simulated Khepera: its pose, wheels, encoders and sensors, and the link between it and its
 * controller. The engine advances it in fixed ticks; everything here is deterministic given the
 * random stream it was built with.
 *
 * <p>What the controller sees follows the serial link: the values visible to it are those the
 * robot-link poll cycle (N, O, H) would have delivered by now at the set baud, and speed commands
 * take effect after their wire time (see {@link LinkTiming}).
 */
public final class SimRobot {
    /** Proximity beams per sensor: the centre ray and two pairs either side model the IR cone. */
    private static final double[] RAY_ANGLES_DEG = {0, 12, -12, 24, -24};
    private static final double[] RAY_WEIGHTS = {1.0, 0.85, 0.85, 0.5, 0.5};
    /** Closer than this to an obstacle (beyond the body radius) counts as touching. */
    private static final double CONTACT_EPSILON_MM = 0.5;
    /** The fast clearance estimate can exceed the true one by up to 2.2 cells; below this margin, refine. */
    private static final double NEAR_MM = 3 * 2.4384;
    /** No sensor sits farther than this from the robot's centre, mm. */
    private static final double SENSOR_REACH_MM = 26.5;
    private static final double TICK_S = Engine.TICK_NANOS / 1e9;
    /** A command's acknowledgement, e.g. {@code d} CR LF. */
    private static final int REPLY_CHARS = 3;

    private final int id;
    private final String name;
    private final World world;
    private final OccupancyGrid grid;
    private final DistanceField field;
    private final Settings settings;
    private final LinkTiming link;
    private final RayHit hit = new RayHit();

    // Pose: position (mm) and heading as a unit vector; the heading angle is derived on demand.
    private double x;
    private double y;
    private double cos;
    private double sin;
    private double clearance;

    // Wheels.
    private int askedLeft;
    private int askedRight;
    private int speedLeft;
    private int speedRight;
    private double wheelLeft;   // actual wheel speeds, mm/s
    private double wheelRight;
    private boolean wheelsDirty = true;
    private long nextMotorNoise;
    private double motorNoiseLeft = 1;
    private double motorNoiseRight = 1;
    private double lastDTheta = Double.NaN;
    private double halfCos = 1;
    private double halfSin;
    private double fullCos = 1;
    private double fullSin;
    private double chordFactor = 1;
    private int ticksSinceNormalise;

    // Encoders, in pulses.
    private double encoderLeft;
    private double encoderRight;

    // Commands on their way down the serial line. Like robot-link, the simulated link sends a
    // speed command only when the asked speeds differ from those last sent, one command at a time:
    // speeds asked for while the line is busy replace each other and the latest goes out next.
    private final CommandQueue commands = new CommandQueue();
    private long lineFreeAt;
    private int sentLeft;
    private int sentRight;
    private boolean speedPending;

    // The poll cycle: values sampled on the robot, and values the controller can see.
    private final long[] eventOffsets;
    private final long cycleNanos;
    private long cycleStart;
    private int phase;
    private final int[] sampledProximity = new int[IrSensor.COUNT];
    private final int[] sampledLight = new int[IrSensor.COUNT];
    private int sampledEncoderLeft;
    private int sampledEncoderRight;
    private final int[] visibleProximity = new int[IrSensor.COUNT];
    private final int[] visibleLight = new int[IrSensor.COUNT];
    private int visibleEncoderLeft;
    private int visibleEncoderRight;

    // The gripper turret: the arm's position moves toward its target at a fixed rate; the fingers
    // report the state they last reached, and a cap between them when they close is held.
    private final Caps caps;
    private double armPos = GripperTurret.ARM_UP;
    private int armTarget = GripperTurret.ARM_UP;
    private ArmPosition armRest = ArmPosition.UP;
    private final double armStepPerTick;
    private GripperState fingers = GripperState.OPEN;
    private GripperState fingerTarget = GripperState.OPEN;
    private long fingersDoneAt = Long.MAX_VALUE;
    private final long fingerNanos;
    private int heldCap = -1;
    private final int capResistivity;
    // Caps near the robot: recheck only after moving capSlack mm or when a cap has moved.
    private int capVersion = -1;
    private double capCheckX;
    private double capCheckY;
    private double capSlack;
    private int blockingCap = -1;
    private final double[] push = new double[2];

    // Contact and statistics.
    private Contact contact = Contact.NONE;
    private boolean blocked;
    private int collisions;
    private double distanceTravelled;
    private final BitSet visited;
    private int visitedFree;
    private final int[] footprint;
    /** For each step (dr, dc) to a neighbouring cell: the footprint's cells not in the footprint before the step. */
    private final int[][] footprintEdges = new int[9][];
    private int lastCellCol = Integer.MIN_VALUE;
    private int lastCellRow = Integer.MIN_VALUE;
    private List<Region> regions;
    private long[] regionEntered;

    // Sensor model, with the per-robot miscalibration drawn once.
    private final ProximityProfile profile;
    private final double proxRange;
    private final double[] sensorX = new double[IrSensor.COUNT];
    private final double[] sensorY = new double[IrSensor.COUNT];
    private final double[] sensorCos = new double[IrSensor.COUNT];
    private final double[] sensorSin = new double[IrSensor.COUNT];
    private final double[] placedX = new double[IrSensor.COUNT];
    private final double[] placedY = new double[IrSensor.COUNT];
    private final double[] placedDx = new double[IrSensor.COUNT];
    private final double[] placedDy = new double[IrSensor.COUNT];
    private final double[] rayCos = new double[RAY_ANGLES_DEG.length];
    private final double[] raySin = new double[RAY_ANGLES_DEG.length];
    private final double[] proxGain = new double[IrSensor.COUNT];
    private final double[] proxOffset = new double[IrSensor.COUNT];
    private final double[] proxNoiseScale = new double[IrSensor.COUNT];
    private final boolean[] proxDead = new boolean[IrSensor.COUNT];
    private final double proxNoiseAbs;
    private final double proxNoiseRel;
    private final double proxSpikeRate;
    private final double[] reflectance;
    private final double[] lightDark = new double[IrSensor.COUNT];
    private final double[] lightGain = new double[IrSensor.COUNT];
    private final boolean[] lightDead = new boolean[IrSensor.COUNT];
    private final double lightBright;
    private final double lightFlickerRate;
    private final double lightFlickerDepth;
    private final double lightNoiseRel;
    private final double readingNoise;
    private final double calibrationLeft;
    private final double calibrationRight;
    private final double motorNoiseSigmaLeft;
    private final double motorNoiseSigmaRight;
    private final double mmPerPulse;
    private List<Light> lights;

    // The robot's own motor modes, used only when something talks to it like a robot (a protocol
    // server): position mode (C and J) and the LEDs. A run with a controller never enters them.
    private final PositionControl positionLeft = new PositionControl();
    private final PositionControl positionRight = new PositionControl();
    private boolean positionMode;
    private long nextPositionUpdate;
    private MotorMode motorMode = MotorMode.SPEED;
    private int leds;

    private final Noise[] proxNoise = new Noise[IrSensor.COUNT];
    private final Noise[] lightNoise = new Noise[IrSensor.COUNT];
    private final Noise motorNoiseL;
    private final Noise motorNoiseR;

    /**
     * @param id the robot's index in the engine
     * @param name a name for reports
     * @param world the world it lives in
     * @param start its start pose
     * @param settings sensor, motor and link settings
     * @param random this robot's own random stream (split from the run's seed)
     */
    SimRobot(int id, String name, World world, Pose start, Settings settings, SplittableRandom random) {
        this.id = id;
        this.name = name;
        this.world = world;
        this.grid = world.grid();
        this.field = world.field();
        this.settings = settings;
        this.link = new LinkTiming((int) settings.number("link.baud"), LinkTiming.DEFAULT_BITS_PER_CHAR,
                (long) (settings.number("link.turnaroundUs") * 1000));
        this.lights = world.arena().lights();
        this.caps = world.capSet();

        // Independent streams, split in a fixed order: adding a source later (split at the end)
        // leaves every existing stream as it was.
        Noise systematic = new Noise(random.split());
        for (int i = 0; i < IrSensor.COUNT; i++) {
            proxNoise[i] = new Noise(random.split());
        }
        for (int i = 0; i < IrSensor.COUNT; i++) {
            lightNoise[i] = new Noise(random.split());
        }
        motorNoiseL = new Noise(random.split());
        motorNoiseR = new Noise(random.split());

        double robotNoise = settings.number("noise.robot");
        readingNoise = settings.number("noise.reading");
        profile = settings.proximityProfile();
        proxRange = profile.rangeMm();
        proxNoiseAbs = settings.number("prox.noiseAbs");
        proxNoiseRel = settings.number("prox.noiseRel");
        proxSpikeRate = settings.number("prox.spikeRate") * readingNoise;
        reflectance = new double[] {0, settings.number("prox.reflect.wall"), settings.number("prox.reflect.light"),
            settings.number("prox.reflect.cap")};
        double offsetSpread = settings.number("prox.offsetSpread");
        double gainSpread = settings.number("prox.gainSpread");
        double darkSpread = settings.number("light.darkSpread");
        for (IrSensor s : IrSensor.values()) {
            int i = s.index();
            sensorX[i] = s.xMm();
            sensorY[i] = s.yMm();
            double h = StrictMath.toRadians(s.headingDeg());
            sensorCos[i] = StrictMath.cos(h);
            sensorSin[i] = StrictMath.sin(h);
            // Always draw, so the streams do not depend on the settings.
            double g = systematic.gaussian();
            double o = systematic.uniform() * 2 - 1;
            double d = systematic.gaussian();
            proxGain[i] = settings.number("prox." + i + ".gain") * (1 + gainSpread * robotNoise * g);
            proxOffset[i] = settings.number("prox.offset") + offsetSpread * robotNoise * o;
            proxNoiseScale[i] = settings.number("prox." + i + ".noise") * readingNoise;
            proxDead[i] = settings.flag("prox." + i + ".dead");
            lightDark[i] = settings.number("light.dark") + darkSpread * robotNoise * d;
            lightGain[i] = settings.number("light." + i + ".gain");
            lightDead[i] = settings.flag("light." + i + ".dead");
        }
        for (int r = 0; r < RAY_ANGLES_DEG.length; r++) {
            rayCos[r] = StrictMath.cos(StrictMath.toRadians(RAY_ANGLES_DEG[r]));
            raySin[r] = StrictMath.sin(StrictMath.toRadians(RAY_ANGLES_DEG[r]));
        }
        lightBright = settings.number("light.bright");
        lightFlickerRate = settings.number("light.flickerRate") * readingNoise;
        lightFlickerDepth = settings.number("light.flickerDepth");
        lightNoiseRel = settings.number("light.noiseRel") * readingNoise;
        double motorSpread = settings.number("motor.spread") * robotNoise;
        calibrationLeft = settings.number("motor.left.calibration") * (1 + motorSpread * systematic.gaussian());
        calibrationRight = settings.number("motor.right.calibration") * (1 + motorSpread * systematic.gaussian());
        motorNoiseSigmaLeft = settings.number("motor.left.noise") * readingNoise;
        motorNoiseSigmaRight = settings.number("motor.right.noise") * readingNoise;
        mmPerPulse = settings.number("encoder.mmPerPulse");
        armStepPerTick = (GripperTurret.ARM_DOWN - GripperTurret.ARM_UP)
                / (settings.number("gripper.armTravelMs") * 1e6 / Engine.TICK_NANOS);
        fingerNanos = (long) StrictMath.rint(settings.number("gripper.fingerMs") * 1e6);
        capResistivity = (int) settings.number("gripper.capResistivity");

        // The poll cycle: for each step, the robot samples when it has read the command and acted,
        // and the controller sees the value when the reply's last character has arrived.
        List<PollStep> steps = LinkTiming.POLL_CYCLE;
        eventOffsets = new long[steps.size() * 2];
        long t = 0;
        for (int i = 0; i < steps.size(); i++) {
            PollStep step = steps.get(i);
            eventOffsets[2 * i] = t + link.wireNanos(step.commandChars()) + link.turnaroundNanos();
            t += link.exchangeNanos(step);
            eventOffsets[2 * i + 1] = t;
        }
        cycleNanos = t;

        visited = new BitSet(grid.cols() * grid.rows());
        regions = world.arena().regions();
        regionEntered = new long[regions.size()];
        java.util.Arrays.fill(regionEntered, -1);
        footprint = footprintOffsets(grid.cellSize());
        for (int dr = -1; dr <= 1; dr++) {
            for (int dc = -1; dc <= 1; dc++) {
                footprintEdges[(dr + 1) * 3 + (dc + 1)] = leadingEdge(footprint, dc, dr);
            }
        }

        x = start.x();
        y = start.y();
        double h = StrictMath.toRadians(start.headingDeg());
        cos = StrictMath.cos(h);
        sin = StrictMath.sin(h);
        clearance = clearanceAt(x, y);
        markVisited(0);

        // robot-link primes every value before it starts the controller; so does the simulator.
        sampleProximity();
        sampleLight();
        sampleEncoders();
        System.arraycopy(sampledProximity, 0, visibleProximity, 0, IrSensor.COUNT);
        System.arraycopy(sampledLight, 0, visibleLight, 0, IrSensor.COUNT);
        visibleEncoderLeft = sampledEncoderLeft;
        visibleEncoderRight = sampledEncoderRight;
        cycleStart = 0;
        phase = 0;
    }

    // ---------------------------------------------------------------- the controller's side

    /**
     * A controller asks for wheel speeds at simulated time {@code now}; the robot acts on them
     * after the command's wire time.
     */
    public void commandSpeeds(long now, int left, int right) {
        askedLeft = left;
        askedRight = right;
        speedPending = left != sentLeft || right != sentRight;
        if (speedPending && now >= lineFreeAt) {
            sendSpeeds(now);
        }
    }

    private void sendSpeeds(long start) {
        long delay = link.speedCommandDelayNanos(askedLeft, askedRight);
        commands.add(start + delay, CommandQueue.SPEED, askedLeft, askedRight);
        lineFreeAt = start + delay + link.wireNanos(REPLY_CHARS);
        sentLeft = askedLeft;
        sentRight = askedRight;
        speedPending = false;
    }

    /** A controller sets the position counters ({@code G}); it waits its turn on the line. */
    public void commandPositions(long now, int left, int right) {
        long start = StrictMath.max(now, lineFreeAt);
        long delay = link.setPositionDelayNanos(left, right);
        commands.add(start + delay, CommandQueue.POSITION, left, right);
        lineFreeAt = start + delay + link.wireNanos(REPLY_CHARS);
    }

    /** Stop the wheels at once: the controller has ended, failed or been stopped (robot-link sends D,0,0). */
    public void emergencyStop() {
        positionMode = false;
        positionLeft.cancel();
        positionRight.cancel();
        motorMode = MotorMode.SPEED;
        askedLeft = 0;
        askedRight = 0;
        commands.clear();
        speedPending = false;
        sentLeft = 0;
        sentRight = 0;
        setSpeedsNow(0, 0);
    }

    /** @param i sensor index @return the proximity value the controller sees now */
    public int visibleProximity(int i) {
        return visibleProximity[i];
    }

    /** @param i sensor index @return the light value the controller sees now */
    public int visibleLight(int i) {
        return visibleLight[i];
    }

    /** @return the left position counter the controller sees now, pulses */
    public int visibleEncoderLeft() {
        return visibleEncoderLeft;
    }

    /** @return the right position counter the controller sees now, pulses */
    public int visibleEncoderRight() {
        return visibleEncoderRight;
    }

    /**
     * A controller moves the gripper arm ({@code T,1,E,pos}); it waits its turn on the line, and the
     * arm starts moving when the command has arrived.
     *
     * @param now simulated time, ns
     * @param position target in the turret's 8-bit units, larger = lower (see {@link GripperTurret})
     */
    public void commandArm(long now, int position) {
        int target = StrictMath.max(0, StrictMath.min(255, position));
        queueTurretCommand(now, CommandQueue.ARM, target, "T,1,E," + target, 3);
    }

    /** @param position up or down, see {@link #commandArm(long, int)} */
    public void commandArm(long now, ArmPosition position) {
        commandArm(now, position == ArmPosition.DOWN ? GripperTurret.ARM_DOWN : GripperTurret.ARM_UP);
    }

    /** A controller opens or closes the fingers ({@code T,1,D,0|1}), after the command's wire time. */
    public void commandFingers(long now, GripperState state) {
        int closed = state == GripperState.CLOSED ? 1 : 0;
        queueTurretCommand(now, CommandQueue.FINGERS, closed, "T,1,D," + closed, 3);
    }

    private void queueTurretCommand(long now, int type, int value, String command, int replyPayload) {
        long start = StrictMath.max(now, lineFreeAt);
        // The command line and CR, then the reply: "t,1," + payload + CR LF.
        long delay = link.wireNanos(command.length() + 1) + link.turnaroundNanos();
        commands.add(start + delay, type, value, 0);
        lineFreeAt = start + delay + link.wireNanos(4 + replyPayload + 2);
    }

    /** @return where the arm last came to rest (while moving: the position it left) */
    public ArmPosition armRest() {
        return armRest;
    }

    /** @return the arm's position now, in the turret's 8-bit units */
    public int armPosition() {
        return (int) StrictMath.rint(armPos);
    }

    /** @return true while the arm travels */
    public boolean armMoving() {
        return armPos != armTarget;
    }

    /** @return the state the fingers last reached (while moving: the state they left) */
    public GripperState fingers() {
        return fingers;
    }

    /** @return the id of the cap the fingers hold, or -1 */
    public int heldCap() {
        return heldCap;
    }

    /**
     * The optical barrier between the fingers: broken by a held cap, or, with the arm low, by
     * anything on the floor crossing the line between the fingers.
     *
     * @return true when something breaks it
     */
    public boolean objectPresent() {
        if (heldCap >= 0) {
            return true;
        }
        if (armPos < GripperTurret.ARM_LOW) {
            return false;
        }
        double half = GripperTurret.OPEN_HALF_GAP_MM - GripperTurret.FINGER_RADIUS_MM;
        // From the left finger's inner face across to the right one's.
        double ox = x + cos * GripperTurret.GRIP_MM - sin * half;
        double oy = y + sin * GripperTurret.GRIP_MM + cos * half;
        return grid.castRay(ox, oy, sin, -cos, 2 * half, hit) != Double.POSITIVE_INFINITY;
    }

    /** @return resistivity of what the fingers hold, 0..255; 0 when they hold nothing */
    public int resistivity() {
        return heldCap >= 0 ? capResistivity : 0;
    }

    /** @return the gripper turret's state now */
    public GripperView gripperView() {
        return new GripperView(armPosition(), armMoving(), fingers, objectPresent(), resistivity(), heldCap);
    }

    /** The arena was edited: pick up its lights and regions, and check the body's clearance again. */
    void arenaEdited() {
        lights = world.arena().lights();
        List<Region> edited = world.arena().regions();
        long[] entered = new long[edited.size()];
        java.util.Arrays.fill(entered, -1);
        for (int k = 0; k < edited.size(); k++) {
            for (int j = 0; j < regions.size(); j++) {
                if (regions.get(j).name().equals(edited.get(k).name())) {
                    entered[k] = regionEntered[j];
                }
            }
        }
        regions = edited;
        regionEntered = entered;
        clearance = clearanceAt(x, y);
        if (heldCap >= caps.count()) {
            heldCap = -1;
        }
        capVersion = -1;
    }

    /** @return the left speed the controller last asked for, units */
    public int askedLeft() {
        return askedLeft;
    }

    /** @return the right speed the controller last asked for, units */
    public int askedRight() {
        return askedRight;
    }

    // ---------------------------------------------------------------- on the robot (a protocol server)

    /**
     * The robot's three motor modes, as its {@code K} status reports them.
     */
    public enum MotorMode {
        /** {@code D}: the wheels hold a speed. */
        SPEED(0),
        /** {@code C}: the wheels move to position targets along a trapezoid profile. */
        POSITION(1),
        /** {@code P}: raw PWM. */
        PWM(2);

        private final int code;

        MotorMode(int code) {
            this.code = code;
        }

        /** @return the number {@code K} reports for this mode */
        public int code() {
            return code;
        }
    }

    /**
     * Set the wheel speeds at once, as the robot does when a {@code D} command has arrived (the
     * serial line is the client's: a protocol server calls this when the command's characters are
     * in). Leaves position and PWM mode.
     *
     * @param left left speed, units (≈ 8 mm/s), -127..127
     * @param right right speed, units
     */
    public void driveSpeeds(int left, int right) {
        leavePositionMode(MotorMode.SPEED);
        askedLeft = left;
        askedRight = right;
        setSpeedsNow(left, right);
    }

    /**
     * Raw PWM ({@code P}), approximated: the simulator has no motor model, so a duty of d/255
     * gives about d/2 speed units (full duty ≈ 127 units ≈ 1 m/s, the robot's top speed).
     *
     * @param left left PWM, -255..255
     * @param right right PWM, -255..255
     */
    public void drivePwm(int left, int right) {
        leavePositionMode(MotorMode.PWM);
        askedLeft = pwmToSpeed(left);
        askedRight = pwmToSpeed(right);
        setSpeedsNow(askedLeft, askedRight);
    }

    /** @param pwm -255..255 @return the speed it gives, units */
    public static int pwmToSpeed(int pwm) {
        return (int) StrictMath.rint(StrictMath.max(-255, StrictMath.min(255, pwm)) * 127.0 / 255.0);
    }

    private void leavePositionMode(MotorMode mode) {
        positionMode = false;
        positionLeft.cancel();
        positionRight.cancel();
        motorMode = mode;
    }

    /**
     * Move the wheels to absolute position-counter targets ({@code C,l,r}) along the profile set by
     * {@link #positionProfile}; the move starts at the next tick and is updated every 10 ms.
     *
     * @param left left target, pulses (0.08 mm)
     * @param right right target, pulses
     */
    public void moveToPositions(int left, int right) {
        positionLeft.moveTo(left, speedLeft);
        positionRight.moveTo(right, speedRight);
        positionMode = true;
        motorMode = MotorMode.POSITION;
        nextPositionUpdate = 0;
    }

    /**
     * The profile of position moves ({@code J,max_l,acc_l,max_r,acc_r}); see {@link PositionControl}.
     *
     * @param maxLeft left maximum speed, units
     * @param accLeft left acceleration, 1/256 unit per 10 ms
     * @param maxRight right maximum speed, units
     * @param accRight right acceleration, 1/256 unit per 10 ms
     */
    public void positionProfile(int maxLeft, int accLeft, int maxRight, int accRight) {
        positionLeft.profile(maxLeft, accLeft);
        positionRight.profile(maxRight, accRight);
    }

    /**
     * The motion status as {@code K} reports it: per wheel (left, then right) whether it is on
     * target (1/0), its mode ({@link MotorMode#code()}), and its error: in position mode the
     * distance to the target in pulses, in speed and PWM mode 0 (the simulated wheel holds the
     * asked speed exactly).
     *
     * @return {Tl, Ml, El, Tr, Mr, Er}
     */
    public int[] motionStatus() {
        int[] k = new int[6];
        status(k, 0, positionLeft, encoderLeft);
        status(k, 3, positionRight, encoderRight);
        return k;
    }

    private void status(int[] k, int at, PositionControl control, double position) {
        k[at + 1] = motorMode.code();
        if (motorMode == MotorMode.POSITION) {
            k[at] = control.onTarget(position) ? 1 : 0;
            k[at + 2] = (int) StrictMath.rint(control.target() - position);
        } else {
            k[at] = 1;
            k[at + 2] = 0;
        }
    }

    /** @return the motor mode now */
    public MotorMode motorMode() {
        return motorMode;
    }

    /**
     * Set the position counters at once ({@code G,l,r} arrived).
     *
     * @param left left counter, pulses
     * @param right right counter, pulses
     */
    public void setCounters(int left, int right) {
        encoderLeft = left;
        encoderRight = right;
    }

    /** @return the left position counter now, pulses (the robot's 32-bit counter) */
    public int counterLeft() {
        return pulses(encoderLeft);
    }

    /** @return the right position counter now, pulses */
    public int counterRight() {
        return pulses(encoderRight);
    }

    /**
     * Read the eight proximity sensors now, with their noise ({@code N} arrived).
     *
     * @param out receives the values, 0..1023, higher = nearer
     */
    public void readProximity(int[] out) {
        sampleProximity();
        System.arraycopy(sampledProximity, 0, out, 0, IrSensor.COUNT);
    }

    /**
     * Read the eight ambient-light sensors now ({@code O} arrived).
     *
     * @param out receives the values, 0..1023, lower = brighter
     */
    public void readLight(int[] out) {
        sampleLight();
        System.arraycopy(sampledLight, 0, out, 0, IrSensor.COUNT);
    }

    /**
     * Send the arm toward a position at once ({@code T,1,E,pos} arrived).
     *
     * @param position 0..255, larger = lower (see {@link GripperTurret})
     */
    public void moveArm(int position) {
        armTarget = StrictMath.max(0, StrictMath.min(255, position));
    }

    /**
     * Start the fingers moving at once ({@code T,1,D,0|1} arrived).
     *
     * @param now simulated time, ns
     * @param state where they go
     */
    public void moveFingers(long now, GripperState state) {
        startFingers(now, state);
    }

    /**
     * An LED command ({@code L,n,action}).
     *
     * @param led 0 lateral, 1 front
     * @param action 0 off, 1 on, 2 toggle
     */
    public void setLed(int led, int action) {
        int bit = 1 << led;
        leds = switch (action) {
            case 0 -> leds & ~bit;
            case 1 -> leds | bit;
            case 2 -> leds ^ bit;
            default -> throw new IllegalArgumentException("LED action " + action + " must be 0 (off), 1 (on) or 2 (toggle)");
        };
    }

    /** @return the LEDs as a bit mask: bit 0 the lateral LED, bit 1 the front LED; 1 = on */
    public int leds() {
        return leds;
    }

    // ---------------------------------------------------------------- the engine's side

    /** Apply what falls due at the start of the tick at {@code now}: commands and poll events. */
    void beginTick(long now) {
        if (speedPending && lineFreeAt <= now) {
            sendSpeeds(lineFreeAt);
        }
        while (commands.size() > 0 && commands.headTime() <= now) {
            int type = commands.headType();
            int a = commands.headA();
            int b = commands.headB();
            commands.pop();
            switch (type) {
                case CommandQueue.SPEED -> setSpeedsNow(a, b);
                case CommandQueue.POSITION -> {
                    encoderLeft = a;
                    encoderRight = b;
                }
                case CommandQueue.ARM -> armTarget = a;
                case CommandQueue.FINGERS -> startFingers(now, a == 1 ? GripperState.CLOSED : GripperState.OPEN);
                default -> throw new IllegalStateException("command type " + type);
            }
        }
        if (positionMode && now >= nextPositionUpdate) {
            nextPositionUpdate = now + Khepera.MOTOR_PERIOD_NANOS;
            setSpeedsNow(positionLeft.update(encoderLeft), positionRight.update(encoderRight));
        }
        if (now >= nextMotorNoise) {
            nextMotorNoise = now + Khepera.MOTOR_PERIOD_NANOS;
            if (motorNoiseSigmaLeft > 0 || motorNoiseSigmaRight > 0) {
                motorNoiseLeft = 1 + motorNoiseSigmaLeft * motorNoiseL.gaussian();
                motorNoiseRight = 1 + motorNoiseSigmaRight * motorNoiseR.gaussian();
                wheelsDirty = true;
            }
        }
        while (cycleStart + eventOffsets[phase] <= now) {
            pollEvent(phase);
            phase++;
            if (phase == eventOffsets.length) {
                phase = 0;
                cycleStart += cycleNanos;
            }
        }
    }

    private void pollEvent(int event) {
        switch (event) {
            case 0 -> sampleProximity();
            case 1 -> System.arraycopy(sampledProximity, 0, visibleProximity, 0, IrSensor.COUNT);
            case 2 -> sampleLight();
            case 3 -> System.arraycopy(sampledLight, 0, visibleLight, 0, IrSensor.COUNT);
            case 4 -> sampleEncoders();
            case 5 -> {
                visibleEncoderLeft = sampledEncoderLeft;
                visibleEncoderRight = sampledEncoderRight;
            }
            default -> throw new IllegalStateException("poll event " + event);
        }
    }

    private void setSpeedsNow(int left, int right) {
        speedLeft = left;
        speedRight = right;
        wheelsDirty = true;
    }

    /**
     * Move the robot through one tick: differential drive, collisions, encoders.
     *
     * @param endNanos simulated time at the end of the tick
     */
    void integrate(long endNanos) {
        if (armPos != armTarget || fingersDoneAt != Long.MAX_VALUE) {
            moveGripper(endNanos);
        }
        if (wheelsDirty) {
            wheelLeft = speedLeft * Khepera.MM_PER_S_PER_SPEED_UNIT * calibrationLeft * motorNoiseLeft;
            wheelRight = speedRight * Khepera.MM_PER_S_PER_SPEED_UNIT * calibrationRight * motorNoiseRight;
            wheelsDirty = false;
        }
        if (speedLeft == 0 && speedRight == 0) {
            return;
        }
        double dl = wheelLeft * TICK_S;
        double dr = wheelRight * TICK_S;
        double common = (dl + dr) * 0.5;
        double diff = (dr - dl) * 0.5;
        double dTheta = (dr - dl) / Khepera.WHEEL_BASE_MM;
        if (dTheta != lastDTheta) {
            lastDTheta = dTheta;
            halfCos = cosSmall(dTheta * 0.5);
            halfSin = sinSmall(dTheta * 0.5);
            fullCos = cosSmall(dTheta);
            fullSin = sinSmall(dTheta);
            chordFactor = dTheta == 0 ? 1 : halfSin / (dTheta * 0.5);
        }
        // Exact arc: the chord points along the mid-tick heading.
        double step = common * chordFactor;
        double midCos = cos * halfCos - sin * halfSin;
        double midSin = sin * halfCos + cos * halfSin;
        double nx = x + step * midCos;
        double ny = y + step * midSin;
        double newClearance = clearanceAt(nx, ny);
        double fraction = 1;
        boolean nowBlocked = false;
        if (newClearance < Khepera.BODY_RADIUS_MM && newClearance < clearance) {
            // Moving into an obstacle: go only as far as the contact, then stop translating. The
            // rotation still happens, and the wheels' common motion stalls (so do the encoders).
            fraction = clearance > Khepera.BODY_RADIUS_MM
                    ? (clearance - Khepera.BODY_RADIUS_MM) / (clearance - newClearance) : 0;
            nx = x + fraction * step * midCos;
            ny = y + fraction * step * midSin;
            newClearance = clearanceAt(nx, ny);
            nowBlocked = true;
            if (!blocked) {
                collisions++;
            }
        }
        double c = cos * fullCos - sin * fullSin;
        double s = sin * fullCos + cos * fullSin;
        if (++ticksSinceNormalise >= 256) {
            double n = 1.0 / StrictMath.sqrt(c * c + s * s);
            c *= n;
            s *= n;
            ticksSinceNormalise = 0;
        }
        blockingCap = -1;
        if (capsNear(nx, ny)) {
            // Caps give way when they can; one that cannot blocks the robot like a wall.
            double tx = nx - x;
            double ty = ny - y;
            if (!capsAllow(nx, ny, c, s)) {
                if (!capsAllow(x, y, c, s)) {
                    c = cos;
                    s = sin;
                    diff = 0;
                }
                double f = 0;
                if (capsAllow(x, y, c, s)) {
                    double hi = 1;
                    for (int k = 0; k < 8; k++) {
                        double mid = (f + hi) * 0.5;
                        if (capsAllow(x + mid * tx, y + mid * ty, c, s)) {
                            f = mid;
                        } else {
                            hi = mid;
                        }
                    }
                }
                nx = x + f * tx;
                ny = y + f * ty;
                fraction *= f;
                newClearance = clearanceAt(nx, ny);
                if (!nowBlocked && !blocked) {
                    collisions++;
                }
                nowBlocked = true;
            }
            pushCaps(nx, ny, c, s);
        }
        blocked = nowBlocked;
        x = nx;
        y = ny;
        clearance = newClearance;
        cos = c;
        sin = s;
        if (heldCap >= 0) {
            caps.carry(heldCap, x + cos * GripperTurret.GRIP_MM, y + sin * GripperTurret.GRIP_MM);
        }
        double moved = common * fraction;
        encoderLeft += (moved - diff) / mmPerPulse;
        encoderRight += (moved + diff) / mmPerPulse;
        distanceTravelled += StrictMath.abs(step * fraction);
        if (clearance <= Khepera.BODY_RADIUS_MM + CONTACT_EPSILON_MM) {
            contact = contactSide(field.nearestObstacleX(x, y), field.nearestObstacleY(x, y));
        } else if (blockingCap >= 0) {
            contact = contactSide(caps.x(blockingCap), caps.y(blockingCap));
        } else {
            contact = Contact.NONE;
        }
        markVisited(endNanos);
    }

    // ---------------------------------------------------------------- the gripper and the caps

    private void startFingers(long now, GripperState target) {
        if (target == fingerTarget) {
            return;
        }
        fingerTarget = target;
        fingersDoneAt = now + fingerNanos;
        if (target == GripperState.OPEN && heldCap >= 0) {
            // The cap falls as soon as the fingers part.
            caps.drop(heldCap, x + cos * GripperTurret.GRIP_MM, y + sin * GripperTurret.GRIP_MM, x, y,
                    Khepera.BODY_RADIUS_MM);
            heldCap = -1;
        }
    }

    private void moveGripper(long endNanos) {
        if (armPos != armTarget) {
            double d = armTarget - armPos;
            armPos = StrictMath.abs(d) <= armStepPerTick ? armTarget : armPos + StrictMath.signum(d) * armStepPerTick;
            if (armPos == armTarget) {
                armRest = armTarget >= GripperTurret.ARM_LOW ? ArmPosition.DOWN : ArmPosition.UP;
            }
        }
        if (fingersDoneAt <= endNanos) {
            fingersDoneAt = Long.MAX_VALUE;
            fingers = fingerTarget;
            if (fingers == GripperState.CLOSED && heldCap < 0 && armPos >= GripperTurret.ARM_LOW) {
                int cap = capBetweenFingers();
                if (cap >= 0) {
                    caps.hold(cap, id);
                    heldCap = cap;
                    caps.carry(cap, x + cos * GripperTurret.GRIP_MM, y + sin * GripperTurret.GRIP_MM);
                }
            }
        }
    }

    /** @return the cap on the floor whose centre lies between the open fingers, nearest the grip point; or -1 */
    private int capBetweenFingers() {
        int best = -1;
        double bestScore = Double.POSITIVE_INFINITY;
        double inner = GripperTurret.OPEN_HALF_GAP_MM - GripperTurret.FINGER_RADIUS_MM;
        for (int i = 0; i < caps.count(); i++) {
            if (caps.heldBy(i) >= 0) {
                continue;
            }
            double dx = caps.x(i) - x;
            double dy = caps.y(i) - y;
            double lx = dx * cos + dy * sin;
            double ly = dy * cos - dx * sin;
            if (lx >= Khepera.BODY_RADIUS_MM - 1 && lx <= GripperTurret.FINGER_TIP_MM && StrictMath.abs(ly) < inner) {
                double score = StrictMath.abs(lx - GripperTurret.GRIP_MM) + StrictMath.abs(ly);
                if (score < bestScore) {
                    bestScore = score;
                    best = i;
                }
            }
        }
        return best;
    }

    /**
     * Whether a cap could touch the robot at (px, py) in any heading. Cheap when none is near: the
     * answer holds until the robot has moved by the distance to the nearest cap or a cap has moved.
     */
    private boolean capsNear(double px, double py) {
        if (caps.count() == 0) {
            return false;
        }
        double dx = px - capCheckX;
        double dy = py - capCheckY;
        if (caps.version() == capVersion && dx * dx + dy * dy < capSlack * capSlack) {
            return false;
        }
        capVersion = caps.version();
        capCheckX = px;
        capCheckY = py;
        double reach = armPos >= GripperTurret.ARM_LOW ? GripperTurret.REACH_MM : Khepera.BODY_RADIUS_MM;
        double gap = caps.nearestSurface(px, py) - reach;
        capSlack = gap > 0 ? gap : 0;
        return gap <= 0;
    }

    /** The parts that push caps: 0 the body, 1 and 2 the lowered fingers, 3 a cap held low. */
    private int pusherCount() {
        if (armPos < GripperTurret.ARM_LOW) {
            return 1;
        }
        return heldCap >= 0 ? 4 : 3;
    }

    /**
     * How far part {@code part} of the robot at pose (px, py, pc, ps) overlaps cap i: writes the
     * displacement that would free the cap into {@link #push} and returns its length (≤ 0: no overlap).
     */
    private double overlap(int part, double px, double py, double pc, double ps, int i) {
        double cx = caps.x(i);
        double cy = caps.y(i);
        double qx;
        double qy;
        double radius;
        if (part == 0) {
            qx = px;
            qy = py;
            radius = Khepera.BODY_RADIUS_MM;
        } else if (part == 3) {
            qx = px + pc * GripperTurret.GRIP_MM;
            qy = py + ps * GripperTurret.GRIP_MM;
            radius = caps.radius(heldCap);
        } else {
            // A finger: the segment from base to tip at its lateral offset; the nearest point on it.
            double side = part == 1 ? 1 : -1;
            double half = fingers == GripperState.CLOSED && fingersDoneAt == Long.MAX_VALUE
                    ? (heldCap >= 0 ? caps.radius(heldCap) : 0) + GripperTurret.FINGER_RADIUS_MM
                    : GripperTurret.OPEN_HALF_GAP_MM;
            double lx = (cx - px) * pc + (cy - py) * ps;
            lx = StrictMath.max(GripperTurret.FINGER_BASE_MM, StrictMath.min(GripperTurret.FINGER_TIP_MM, lx));
            double ly = side * half;
            qx = px + pc * lx - ps * ly;
            qy = py + ps * lx + pc * ly;
            radius = GripperTurret.FINGER_RADIUS_MM;
        }
        double ex = cx - qx;
        double ey = cy - qy;
        double d2 = ex * ex + ey * ey;
        double touch = radius + caps.radius(i);
        if (d2 >= touch * touch) {
            return 0;
        }
        double d = StrictMath.sqrt(d2);
        if (d == 0) {
            // Dead centre: push straight ahead.
            ex = pc;
            ey = ps;
            d = 1;
        }
        double need = touch - d + 1e-9;
        push[0] = ex / d * need;
        push[1] = ey / d * need;
        return need;
    }

    /** Whether every cap the robot at this pose overlaps can give way (nothing moves). */
    private boolean capsAllow(double px, double py, double pc, double ps) {
        int parts = pusherCount();
        for (int i = 0; i < caps.count(); i++) {
            if (caps.heldBy(i) >= 0) {
                continue;
            }
            for (int part = 0; part < parts; part++) {
                if (overlap(part, px, py, pc, ps, i) > 0 && caps.reach(i, push[0], push[1], Caps.CHAIN - 1) < 1) {
                    blockingCap = i;
                    return false;
                }
            }
        }
        return true;
    }

    /** Push every cap the robot at this pose overlaps out of its way. */
    private void pushCaps(double px, double py, double pc, double ps) {
        int parts = pusherCount();
        for (int i = 0; i < caps.count(); i++) {
            if (caps.heldBy(i) >= 0) {
                continue;
            }
            for (int part = 0; part < parts; part++) {
                if (overlap(part, px, py, pc, ps, i) > 0) {
                    caps.push(i, push[0], push[1], Caps.CHAIN - 1);
                }
            }
        }
    }

    /** Clearance of the body's centre: the fast estimate, refined where contact is possible. */
    private double clearanceAt(double px, double py) {
        double c = field.clearance(px, py);
        return c < Khepera.BODY_RADIUS_MM + NEAR_MM ? field.preciseClearance(px, py) : c;
    }

    /**
     * sin of a per-tick turn (|a| ≤ 0.04 rad at full speed): its Taylor series to the a⁹ term is
     * exact to double precision there, plain arithmetic, and several times cheaper than StrictMath.
     */
    private static double sinSmall(double a) {
        if (StrictMath.abs(a) > 0.1) {
            return StrictMath.sin(a);
        }
        double a2 = a * a;
        return a * (1 - a2 / 6 * (1 - a2 / 20 * (1 - a2 / 42 * (1 - a2 / 72))));
    }

    /** cos of a per-tick turn; see {@link #sinSmall}. */
    private static double cosSmall(double a) {
        if (StrictMath.abs(a) > 0.1) {
            return StrictMath.cos(a);
        }
        double a2 = a * a;
        return 1 - a2 / 2 * (1 - a2 / 12 * (1 - a2 / 30 * (1 - a2 / 56 * (1 - a2 / 90))));
    }

    private Contact contactSide(double obstacleX, double obstacleY) {
        double ox = obstacleX - x;
        double oy = obstacleY - y;
        double rel = StrictMath.atan2(oy, ox) - StrictMath.atan2(sin, cos);
        return Contact.ofAngle(rel);
    }

    // ---------------------------------------------------------------- sensors

    /** Where each sensor is in the arena now, and which way it looks. */
    private void placeSensors() {
        for (int i = 0; i < IrSensor.COUNT; i++) {
            placedX[i] = x + cos * sensorX[i] - sin * sensorY[i];
            placedY[i] = y + sin * sensorX[i] + cos * sensorY[i];
            placedDx[i] = cos * sensorCos[i] - sin * sensorSin[i];
            placedDy[i] = sin * sensorCos[i] + cos * sensorSin[i];
        }
    }

    private void sampleProximity() {
        placeSensors();
        // Caps are not in the distance field: bound the beams' empty stretch by the nearest cap too.
        double capFree = caps.count() == 0 ? Double.POSITIVE_INFINITY
                : caps.nearestSurface(x, y) - SENSOR_REACH_MM;
        for (int i = 0; i < IrSensor.COUNT; i++) {
            double px = placedX[i];
            double py = placedY[i];
            double dx = placedDx[i];
            double dy = placedDy[i];
            double raw = 0;
            double free = field.clearance(px, py);
            if (capFree < free) {
                free = StrictMath.min(free, capsAhead(px, py, dx, dy));
            }
            if (free < proxRange) {
                // Nothing lies nearer than the clearance (less the estimate's error): start the
                // beams there instead of walking the empty cells.
                double skip = StrictMath.max(0, free - NEAR_MM);
                for (int r = 0; r < rayCos.length; r++) {
                    double rx = dx * rayCos[r] - dy * raySin[r];
                    double ry = dy * rayCos[r] + dx * raySin[r];
                    double d = skip + grid.castRay(px + skip * rx, py + skip * ry, rx, ry, proxRange - skip, hit);
                    if (d != Double.POSITIVE_INFINITY) {
                        double v = RAY_WEIGHTS[r] * reflectanceOf(hit.id) * profile.valueAt(d);
                        if (v > raw) {
                            raw = v;
                        }
                    }
                }
            }
            double value = raw * proxGain[i] + proxOffset[i];
            if (proxNoiseScale[i] > 0) {
                Noise n = proxNoise[i];
                value += n.gaussian() * (proxNoiseAbs + proxNoiseRel * raw) * proxNoiseScale[i];
                if (n.uniform() < proxSpikeRate) {
                    value = n.uniform() * 1023;
                }
            }
            sampledProximity[i] = proxDead[i] ? 0 : clampReading(value);
        }
    }

    /**
     * Distance from a sensor to the nearest cap on the floor that its beams could reach: caps
     * wholly behind the sensor (all the beams point forward) do not count.
     */
    private double capsAhead(double px, double py, double dx, double dy) {
        double best = Double.POSITIVE_INFINITY;
        for (int k = 0; k < caps.count(); k++) {
            if (caps.heldBy(k) >= 0) {
                continue;
            }
            double ex = caps.x(k) - px;
            double ey = caps.y(k) - py;
            double r = caps.radius(k);
            if (ex * dx + ey * dy < -r) {
                continue;
            }
            double d = StrictMath.sqrt(ex * ex + ey * ey) - r;
            if (d < best) {
                best = d;
            }
        }
        return best;
    }

    private double reflectanceOf(int cellId) {
        return cellId >= OccupancyGrid.FIRST_CAP ? reflectance[3] : reflectance[cellId];
    }

    private void sampleLight() {
        placeSensors();
        for (int i = 0; i < IrSensor.COUNT; i++) {
            double px = placedX[i];
            double py = placedY[i];
            double dx = placedDx[i];
            double dy = placedDy[i];
            double exposure = 0;
            for (int k = 0; k < lights.size(); k++) {
                exposure += exposure(lights.get(k), px, py, dx, dy);
            }
            double dark = lightDark[i];
            Noise n = lightNoise[i];
            double value;
            if (exposure <= 0 || lightDead[i]) {
                value = dark;
                if (lightFlickerRate > 0 && n.uniform() < lightFlickerRate) {
                    value *= 1 + lightFlickerDepth * (n.uniform() * 2 - 1);
                }
            } else {
                double e = StrictMath.min(1, exposure * lightGain[i]);
                value = dark - (dark - lightBright) * e;
                if (lightNoiseRel > 0) {
                    value += n.gaussian() * lightNoiseRel * (dark - value);
                }
            }
            sampledLight[i] = clampReading(value);
        }
    }

    /** How much of a light reaches a sensor at (px, py) looking along (dx, dy); 0..intensity. */
    private double exposure(Light light, double px, double py, double dx, double dy) {
        double lx = light.x() - px;
        double ly = light.y() - py;
        double r = StrictMath.sqrt(lx * lx + ly * ly);
        if (r >= light.range()) {
            return 0;
        }
        double facing = r == 0 ? 1 : (lx * dx + ly * dy) / r;
        if (facing <= 0) {
            return 0;
        }
        if (light.isDirectional()) {
            double dir = StrictMath.toRadians(light.directionDeg());
            double towards = r == 0 ? 1 : -(lx * StrictMath.cos(dir) + ly * StrictMath.sin(dir)) / r;
            if (towards < StrictMath.cos(StrictMath.toRadians(light.spreadDeg() / 2))) {
                return 0;
            }
        }
        if (!grid.lightReaches(px, py, light.x(), light.y())) {
            return 0;
        }
        double falloff = 1 - r / light.range();
        return light.intensity() * facing * falloff * falloff;
    }

    private void sampleEncoders() {
        sampledEncoderLeft = pulses(encoderLeft);
        sampledEncoderRight = pulses(encoderRight);
    }

    /** The 32-bit counter's value for a wheel travel of {@code count} pulses (it wraps like the robot's). */
    private static int pulses(double count) {
        return (int) (long) StrictMath.floor(count);
    }

    private static int clampReading(double v) {
        if (v <= 0) {
            return 0;
        }
        if (v >= 1023) {
            return 1023;
        }
        return (int) StrictMath.floor(v + 0.5);
    }

    // ---------------------------------------------------------------- statistics

    private static int[] footprintOffsets(double cell) {
        int reach = (int) StrictMath.ceil(Khepera.BODY_RADIUS_MM / cell);
        int[] tmp = new int[(2 * reach + 1) * (2 * reach + 1) * 2];
        int n = 0;
        for (int dr = -reach; dr <= reach; dr++) {
            for (int dc = -reach; dc <= reach; dc++) {
                if (StrictMath.hypot(dc * cell, dr * cell) <= Khepera.BODY_RADIUS_MM) {
                    tmp[n++] = dc;
                    tmp[n++] = dr;
                }
            }
        }
        return java.util.Arrays.copyOf(tmp, n);
    }

    /** Offsets of {@code disc} that are not offsets of the disc shifted back by (dc, dr). */
    private static int[] leadingEdge(int[] disc, int dc, int dr) {
        java.util.Set<Long> before = new java.util.HashSet<>();
        for (int k = 0; k < disc.length; k += 2) {
            before.add(((long) (disc[k] - dc) << 32) ^ ((disc[k + 1] - dr) & 0xFFFFFFFFL));
        }
        int[] out = new int[disc.length];
        int n = 0;
        for (int k = 0; k < disc.length; k += 2) {
            if (!before.contains(((long) disc[k] << 32) ^ (disc[k + 1] & 0xFFFFFFFFL))) {
                out[n++] = disc[k];
                out[n++] = disc[k + 1];
            }
        }
        return java.util.Arrays.copyOf(out, n);
    }

    private void markVisited(long timeNanos) {
        int col = grid.col(x);
        int row = grid.row(y);
        if (col == lastCellCol && row == lastCellRow) {
            return;
        }
        for (int k = 0; k < regions.size(); k++) {
            if (regionEntered[k] < 0 && regions.get(k).contains(x, y)) {
                regionEntered[k] = timeNanos;
            }
        }
        int lastCol = lastCellCol;
        int lastRow = lastCellRow;
        lastCellCol = col;
        lastCellRow = row;
        int dc = col - lastCol;
        int dr = row - lastRow;
        // A step to a neighbouring cell only uncovers the disc's leading edge in that direction.
        int[] offsets = lastCol != Integer.MIN_VALUE && StrictMath.abs(dc) <= 1 && StrictMath.abs(dr) <= 1
                ? footprintEdges[(dr + 1) * 3 + (dc + 1)] : footprint;
        for (int k = 0; k < offsets.length; k += 2) {
            int c = col + offsets[k];
            int r = row + offsets[k + 1];
            if (c >= 0 && r >= 0 && c < grid.cols() && r < grid.rows()) {
                int idx = r * grid.cols() + c;
                if (!visited.get(idx)) {
                    visited.set(idx);
                    if (grid.id(c, r) == OccupancyGrid.FLOOR) {
                        visitedFree++;
                    }
                }
            }
        }
    }

    // ---------------------------------------------------------------- read-only views

    /** @return the robot's index in the engine */
    public int id() {
        return id;
    }

    /** @return the robot's name */
    public String name() {
        return name;
    }

    /** @return x, mm */
    public double x() {
        return x;
    }

    /** @return y, mm */
    public double y() {
        return y;
    }

    /** @return heading, degrees counter-clockwise from +x, in (−180, 180] */
    public double headingDeg() {
        return StrictMath.toDegrees(StrictMath.atan2(sin, cos));
    }

    /** @return the speeds in effect on the wheels, units */
    public int speedLeft() {
        return speedLeft;
    }

    /** @return the speeds in effect on the wheels, units */
    public int speedRight() {
        return speedRight;
    }

    /** @return the robot's own left position counter, pulses (not delayed by the link) */
    public int encoderLeft() {
        return pulses(encoderLeft);
    }

    /** @return the robot's own right position counter, pulses */
    public int encoderRight() {
        return pulses(encoderRight);
    }

    /** @return which side touches an obstacle */
    public Contact contact() {
        return contact;
    }

    /** @return true when the last tick's move was stopped by an obstacle */
    public boolean blocked() {
        return blocked;
    }

    /** @return number of times a move was stopped by an obstacle after moving freely */
    public int collisions() {
        return collisions;
    }

    /** @return path length of the robot's centre, mm */
    public double distanceTravelledMm() {
        return distanceTravelled;
    }

    /** @return percentage of the arena's floor cells the robot's body has covered */
    public double visitedPercent() {
        return world.freeCells() == 0 ? 0 : 100.0 * visitedFree / world.freeCells();
    }

    /**
     * @return the named regions of the arena the robot's centre has entered, with the simulated
     *     time of the first entry in seconds, in arena order
     */
    public java.util.Map<String, Double> regionsEntered() {
        java.util.Map<String, Double> out = new java.util.LinkedHashMap<>();
        for (int k = 0; k < regions.size(); k++) {
            if (regionEntered[k] >= 0) {
                out.put(regions.get(k).name(), regionEntered[k] / 1e9);
            }
        }
        return out;
    }

    /** @return the link timing this robot's controller lives with */
    public LinkTiming link() {
        return link;
    }

    /** @return the settings this robot was built with */
    public Settings settings() {
        return settings;
    }

    /** Copy the visible values into a snapshot's arrays without allocating. */
    void copyVisible(int[] prox, int[] light) {
        System.arraycopy(visibleProximity, 0, prox, 0, IrSensor.COUNT);
        System.arraycopy(visibleLight, 0, light, 0, IrSensor.COUNT);
    }

    /** A fixed-capacity FIFO of commands in flight, allocation-free. */
    private static final class CommandQueue {
        static final int SPEED = 0;
        static final int POSITION = 1;
        static final int ARM = 2;
        static final int FINGERS = 3;
        private long[] time = new long[16];
        private int[] type = new int[16];
        private int[] a = new int[16];
        private int[] b = new int[16];
        private int head;
        private int size;

        void add(long t, int kind, int va, int vb) {
            if (size == time.length) {
                grow();
            }
            int i = (head + size) % time.length;
            time[i] = t;
            type[i] = kind;
            a[i] = va;
            b[i] = vb;
            size++;
        }

        private void grow() {
            int n = time.length * 2;
            long[] t2 = new long[n];
            int[] ty2 = new int[n];
            int[] a2 = new int[n];
            int[] b2 = new int[n];
            for (int k = 0; k < size; k++) {
                int i = (head + k) % time.length;
                t2[k] = time[i];
                ty2[k] = type[i];
                a2[k] = a[i];
                b2[k] = b[i];
            }
            time = t2;
            type = ty2;
            a = a2;
            b = b2;
            head = 0;
        }

        int size() {
            return size;
        }

        long headTime() {
            return time[head];
        }

        int headType() {
            return type[head];
        }

        int headA() {
            return a[head];
        }

        int headB() {
            return b[head];
        }

        void pop() {
            head = (head + 1) % time.length;
            size--;
        }

        void clear() {
            size = 0;
        }
    }
}
