package org.kheperasim.sim.engine;

import java.util.Map;
import java.util.SplittableRandom;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.body.CapContacts;
import org.kheperasim.sim.engine.body.DriveBody;
import org.kheperasim.sim.engine.body.GripperModel;
import org.kheperasim.sim.engine.body.GripperPort;
import org.kheperasim.sim.engine.link.LinkEnd;
import org.kheperasim.sim.engine.link.RobotLink;
import org.kheperasim.sim.engine.model.LoopTiming;
import org.kheperasim.sim.engine.model.Miscalibration;
import org.kheperasim.sim.engine.model.RobotModel;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.model.Ticks;
import org.kheperasim.sim.engine.model.VisionModel;
import org.kheperasim.sim.engine.noise.CounterNoise;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.sensing.Coverage;
import org.kheperasim.sim.engine.sensing.LightSensing;
import org.kheperasim.sim.engine.sensing.LinearCamera;
import org.kheperasim.sim.engine.sensing.ProximitySensing;
import org.kheperasim.sim.engine.sensing.SamplePose;
import org.kheperasim.sim.engine.sensing.Scans;
import org.kheperasim.sim.engine.sensing.SensorPlacement;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.Contact;
import org.kheperasim.sim.engine.view.DriverRecorder;

/**
 * One simulated robot of a {@link RobotType}, assembled from the parts it models: the {@link DriveBody} on its wheels,
 * the {@link ProximitySensing} and {@link LightSensing}, the {@link GripperModel} with its
 * {@link CapContacts}, the {@link RobotLink} its controller talks through (and the {@link LinkEnd}
 * where the link meets the parts), the robot's own
 * {@link OnBoardControl}, its {@link Coverage} and its {@link Miscalibration}.
 *
 * <p>This class wires them together and tells the engine when the robot next needs attention
 * ({@link #nextDueNanos}) and how far it can glide before a contact or a region entry could happen
 * ({@link #glideTicks}). Everything is deterministic given the robot's noise streams.
 */
public final class SimRobot {
    private final int id;
    private final String name;
    private final Settings settings;
    private final RobotModel model;
    private final DriveBody body;
    private final SensorPlacement placement;
    private final ProximitySensing proximity;
    private final LightSensing light;
    private final GripperModel gripper;
    private final CapContacts capContacts;
    /** Another robot's surface farther than this from the centre is out of every sensor's reach, mm. */
    private final double unseenMm;
    private final RobotLink link;
    private final OnBoardControl onBoard;
    private final Coverage coverage;
    private final GripperPort gripperPort;
    private long nextDue;
    /** Simulated time the robot has been moved to, ns. */
    private long movedTo;
    private long nextHardDue;
    /** Where the robot is for the sample being taken. */
    private final SamplePose sense;
    /** What the link's commands and poll samples do to the parts. */
    private final LinkEnd end;
    private final Glides glides;
    private final ControllerLink controls;
    private final World world;
    private final LinearCamera camera;
    /** Draws for the lengthened loop pauses of {@code wsu.loopTiming=desktop}; null when pauses are exact. */
    private final CounterNoise loopTiming;
    /** The robot's own 20 ms sensor scan, which every reader of a sensor gets. */
    private final Scans scans;
    /** The controller on the robot's processor, or null: it runs through the serial link. */
    private OnBoardLink onBoardLink;
    /** What the run hands the controller. */
    private org.kheperasim.api.Parameters parameters = org.kheperasim.api.Parameters.NONE;
    /** Hears the commands and emergency stops (a command log), or null. */
    private DriverRecorder recorder;
    /** Told the end of every move, ns (the engine's events, {@code engine.event}), or null: none. */
    private java.util.function.ObjLongConsumer<SimRobot> moveWatch;

    /**
     * @param id the robot's index in the engine
     * @param name a name for reports
     * @param world the world it lives in
     * @param start its start pose
     * @param settings sensor, motor and link settings
     * @param type the robot's type: body, wheels, sensors
     * @param random this robot's own random stream (split from the run's seed): each noise source's
     *     key is drawn from it in a fixed order, so adding a source at the end shifts no other
     */
    SimRobot(int id, String name, World world, Pose start, Settings settings, RobotType type, SplittableRandom random) {
        this.id = id;
        this.name = name;
        this.world = world;
        this.settings = settings;
        this.model = RobotModel.of(settings, type);
        this.placement = new SensorPlacement(type);
        CounterNoise systematic = new CounterNoise(random.nextLong());
        CounterNoise[] proxNoise = streams(random, type.sensorCount());
        CounterNoise[] lightNoise = streams(random, type.sensorCount());
        CounterNoise motorLeft = new CounterNoise(random.nextLong());
        CounterNoise motorRight = new CounterNoise(random.nextLong());
        Miscalibration calibration = new Miscalibration(model, systematic);
        this.body = new DriveBody(world, id, start.x(), start.y(), start.headingDeg(), type, model.motors(),
                model.noise().reading(), calibration.calibrationLeft, calibration.calibrationRight,
                motorLeft, motorRight);
        this.sense = new SamplePose(body);
        this.proximity = new ProximitySensing(world, id, placement, model, calibration, proxNoise);
        this.light = new LightSensing(world, placement, model, calibration, lightNoise);
        this.gripper = new GripperModel(id, world, body, model.gripper());
        proximity.armInView(gripper, settings.raw("gripper.armInView"));
        this.capContacts = new CapContacts(world.capSet(), gripper, id, body.radius());
        this.gripperPort = new GripperPort(gripper);
        this.onBoard = new OnBoardControl(this, body, gripper, type.drive());
        this.coverage = new Coverage(world, start.x(), start.y(), body.radius());
        this.unseenMm = placement.reachMm + model.proximity().profile().rangeMm() + 1;
        this.glides = new Glides(model, body, gripper, capContacts, coverage);
        this.scans = new Scans(sense, proximity, light, coverage, !world.arena().lights().isEmpty(),
                type.sensorCount());
        this.end = new LinkEnd(body, sense, gripper, light, scans);
        this.link = new RobotLink(model.link().timing(), end, type.sensorCount());
        this.controls = new ControllerLink(this, link);
        // The turret's stream is drawn last, so that it shifts none of the others.
        this.camera = new LinearCamera(world, id, body, VisionModel.of(settings), new CounterNoise(random.nextLong()));
        // Drawn after the turret's, and only when used: it shifts no other stream.
        this.loopTiming = LoopTiming.desktop(settings) ? new CounterNoise(random.nextLong()) : null;
        sense.at(0);
        scans.taking(Scans.Taking.EVERY, 0);
        scans.capture(0, true);
        link.prime();
    }

    private static CounterNoise[] streams(SplittableRandom random, int count) {
        CounterNoise[] out = new CounterNoise[count];
        for (int i = 0; i < out.length; i++) {
            out[i] = new CounterNoise(random.nextLong());
        }
        return out;
    }

    // ------------------------------------------------------------------ the engine's side

    /** Apply what falls due at the tick at {@code now}: commands, the scan, poll samples, noise, position moves. */
    void beginTick(long now) {
        if (now < nextDue) {
            return;
        }
        link.commandsDue(now);
        sense.at(0);
        // The world stops here: the scan is computed at once, seeing every robot and cap where they are.
        captureDue(now, true);
        link.pollDue(now);
        long due = StrictMath.min(link.nextCommandDue(), body.wheels().noiseDue(now));
        nextHardDue = StrictMath.min(due, onBoard.due(now));
        nextDue = StrictMath.min(nextHardDue, nextSenseDue());
    }

    /** Take the scan of the tick at {@code now} if it is wanted; the sample pose is at that tick. */
    private void captureDue(long now, boolean computeNow) {
        long tick = now / Ticks.NANOS;
        if (scans.nextTick() == tick) {
            scans.capture(tick, computeNow);
        }
    }

    /** @return when the robot next takes a scan or a poll sample, ns ({@link Long#MAX_VALUE}: neither) */
    private long nextSenseDue() {
        long t = scans.nextTick();
        return StrictMath.min(link.nextPollDue(), t == Long.MAX_VALUE ? Long.MAX_VALUE : t * Ticks.NANOS);
    }

    /** @return the tick of the robot's next scan (far in the future: none wanted) */
    long nextScanTick() {
        long t = scans.nextTick();
        return t == Long.MAX_VALUE ? Long.MAX_VALUE / 2 : t;
    }

    /**
     * A program on the robot will read its sensors at {@code readAt}: the scan of that window is taken.
     *
     * @param readAt simulated time, ns ({@link Long#MAX_VALUE}: never)
     */
    void wantScan(long readAt) {
        scans.want(readAt);
        nextDue = StrictMath.min(nextDue, nextSenseDue());
    }

    /** The robot moves among others, or the arena is edited: values left for a later read are computed now. */
    void settleScan() {
        scans.settle();
    }

    /**
     * The controller runs on the robot's own processor from now on (on-board): no serial link, it
     * reads the latest scan and its commands act at once. Call before the controller is made.
     *
     * @param readsAtWakes true when it reads only when its driver wakes (a step controller: the
     *     engine then has the scans of those windows taken, no others); false for a controller that
     *     may read at any moment (every scan is taken)
     */
    public void runOnBoard(boolean readsAtWakes) {
        onBoardLink = new OnBoardLink(this, body, gripper, scans);
        controls.onBoard(onBoardLink);
        link.stopPolling();
        scans.taking(readsAtWakes ? Scans.Taking.WANTED : Scans.Taking.EVERY, movedTo);
        nextDue = StrictMath.min(nextHardDue, nextSenseDue());
    }

    /** @param given the numbers the run hands the robot's controller (see {@link org.kheperasim.api.Parameters}) */
    public void parameters(org.kheperasim.api.Parameters given) {
        this.parameters = java.util.Objects.requireNonNull(given);
    }

    /** @return the numbers the run hands the robot's controller */
    public org.kheperasim.api.Parameters parameters() {
        return parameters;
    }

    /** @return true when the controller runs on the robot (see {@link #runOnBoard}) */
    public boolean runsOnBoard() {
        return onBoardLink != null;
    }

    /** The controller's modes, as a command log and a trace header name them. */
    public static final String TETHERED = "tethered";
    /** On the robot, reading when it wakes (a step controller). */
    public static final String ON_BOARD_STEPS = "onboard-steps";
    /** On the robot, reading at any time. */
    public static final String ON_BOARD = "onboard";

    /** @return where the controller runs: {@link #TETHERED}, {@link #ON_BOARD_STEPS} or {@link #ON_BOARD} */
    public String controlMode() {
        return onBoardLink == null ? TETHERED : scans.readsAtWakes() ? ON_BOARD_STEPS : ON_BOARD;
    }

    /**
     * @param mode where the controller runs, as {@link #controlMode} names it (a replay sets the run's up again)
     * @throws IllegalArgumentException for another word
     */
    public void controlMode(String mode) {
        switch (mode) {
            case TETHERED -> { }
            case ON_BOARD_STEPS -> runOnBoard(true);
            case ON_BOARD -> runOnBoard(false);
            default -> throw new IllegalArgumentException("unknown controller mode '" + mode + "': " + TETHERED + ", "
                    + ON_BOARD_STEPS + " or " + ON_BOARD);
        }
    }

    /**
     * @return when this robot next needs the engine to stop at a tick, ns: a command, a noise
     *     redraw, a position-move update (poll samples inside a glide are taken on the way)
     */
    long nextDueNanos() {
        return nextHardDue;
    }

    /**
     * @param wanted how many ticks the caller would glide at most
     * @return how many ticks the robot can glide from here with no wall, lamp or cap to touch and no
     *     region to enter on the way (0: step the next tick with contact handling), or at least
     *     {@code wanted}; the caller has made sure that no other robot can touch it meanwhile
     */
    long glideTicks(long wanted) {
        return glides.ticks(wanted);
    }

    /** @return true when the robot may be only turning on the spot: still, or stalled against another robot */
    boolean frozen() {
        return moveWatch == null && body.frozen();
    }

    /**
     * @param from the first tick asked about
     * @param wanted the most ticks asked about
     * @return how many ticks from {@code from} (up to {@code wanted}) the robot would only turn on the spot, if no
     *     robot it may touch moves meanwhile, with no poll sample due ({@link DriveBody#stalledTicks})
     */
    long stalledTicks(long from, long wanted) {
        long poll = link.nextPollDue();
        if (poll != Long.MAX_VALUE) {
            wanted = StrictMath.min(wanted, ceilTick(poll) / Ticks.NANOS - from);
        }
        return wanted <= 0 ? 0 : body.stalledTicks(wanted);
    }

    /** Drive {@code ticks} ticks ending at {@code endNanos} that {@link #stalledTicks} allowed. */
    void turnStalled(long ticks, long endNanos, int[] mates, int mateCount) {
        body.turnStalled(ticks, capContacts, mates, mateCount);
        movedTo = endNanos;
        gripper.moved(endNanos);
        coverage.regionsAt(body.x(), body.y(), endNanos);
    }

    /** @return how far the centre travels in one tick at most at the present wheel speeds, mm */
    double travelPerTickMm() {
        return body.wheels().travelPerTickMm();
    }

    /** @return another robot's surface farther than this from the centre is out of every sensor's reach, mm */
    double unseenMm() {
        return unseenMm;
    }

    /** @return the body's radius, mm */
    double radiusMm() {
        return body.radius();
    }

    /** @return the robot's type: its body, wheels and sensors */
    public RobotType type() {
        return model.type();
    }


    /**
     * Move through {@code ticks} ticks ending at {@code endNanos}: a glide, which {@link #glideTicks}
     * must allow, or one tick with contact handling.
     *
     * @param mates the only other robots it may touch meanwhile, or null: any (see {@link
     *     Bodies#freeFraction}); its mover knows this from how far apart the robots are
     * @param mateCount how many of {@code mates} count
     */
    void move(long ticks, long endNanos, boolean glide, int[] mates, int mateCount) {
        if (glide) {
            long start = endNanos - ticks * Ticks.NANOS;
            // Scans and poll samples that fall inside the glide are taken where the robot is at their
            // tick. Gliding, it is alone (no other robot can come within its sensors' reach): a scan's
            // proximity values can wait for their first read, unless a cap or the gripper may move meanwhile.
            boolean computeNow = mayMoveCaps(ticks + Scans.PERIOD_TICKS);
            long due = nextSenseDue();
            while (due < endNanos) {
                long at = ceilTick(due);
                if (at >= endNanos) {
                    break;
                }
                sense.at((at - start) / Ticks.NANOS);
                captureDue(at, computeNow);
                link.pollDue(at);
                due = nextSenseDue();
            }
            nextDue = StrictMath.min(nextHardDue, due);
            body.glide(ticks);
        } else {
            // A step among others that may touch it: its own poll samples of this tick first (they read
            // only its own scan and counters), then the step.
            long start = endNanos - Ticks.NANOS;
            if (link.nextPollDue() <= start) {
                sense.at(0);
                link.pollDue(start);
                nextDue = StrictMath.min(nextHardDue, nextSenseDue());
            }
            body.step(capContacts, mates, mateCount);
        }
        movedTo = endNanos;
        gripper.moved(endNanos);
        coverage.regionsAt(body.x(), body.y(), endNanos);
        if (moveWatch != null) {
            moveWatch.accept(this, endNanos);
        }
    }

    /** @param watch told the end of this robot's every move, ns, on the thread that moves it; null: none */
    public void watchMoves(java.util.function.ObjLongConsumer<SimRobot> watch) {
        this.moveWatch = watch;
    }

    /** @return the point the body touches, {x, y} mm (the last one; meaningful while {@link #contact} is not NONE) */
    public double[] touchPoint() {
        return body.touchPoint();
    }

    private static long ceilTick(long nanos) {
        return -Math.floorDiv(-nanos, Ticks.NANOS) * Ticks.NANOS;
    }

    // ------------------------------------------------------------------ moving among others (Crowd)

    /**
     * The proximity samples to come may see only robots {@code ids[from .. to)} (null: any): the
     * mover knows no other robot can come within their reach meanwhile.
     */
    void sightScope(int[] ids, int from, int to) {
        proximity.scope(ids, from, to);
    }

    /**
     * Take the scan due at the tick at {@code now}, where the robot has been moved to (and every robot
     * that may come within its sensors' reach), and the poll samples due then.
     */
    void scanAt(long now) {
        sense.at(0);
        captureDue(now, true);
        link.pollDue(now);
        nextDue = StrictMath.min(nextHardDue, nextSenseDue());
    }

    /**
     * @param ticks a stretch's length
     * @return true when the robot may move a cap during the stretch: it steps every tick (the
     *     reference), its gripper moves or holds a cap, or a cap is within its parts' reach of travel
     */
    boolean mayMoveCaps(long ticks) {
        return steppingByTicks() || gripper.busy() || gripper.heldCap() >= 0
                || capContacts.freeTravelMm(body.x(), body.y()) <= body.wheels().travelPerTickMm() * ticks + 1e-6;
    }

    /** @return true when the robot's model steps every tick, the reference the event stepping is tested against */
    boolean steppingByTicks() {
        return model.stepping() == RobotModel.Stepping.TICK;
    }

    /** A protocol client drives the robot itself: the simulated controller's link stops polling. */
    void servedDirectly() {
        link.stopPolling();
    }

    /** Speeds set on the robot itself: what the controller's side last asked for too. */
    void asked(int left, int right) {
        link.asked(left, right);
    }

    /** Sample the proximity sensors where the robot is now (a protocol client's {@code N}); snapshots show them. */
    void readProximityNow(int[] out) {
        scanReady();
        end.sampleProximity(movedTo, out);
        link.reportedProximity(out);
    }

    /**
     * The robot is read where it has been moved to, between ticks: a scan due at that very tick is
     * taken first (the world is there, as at the start of the tick).
     */
    private void scanReady() {
        long tick = movedTo / Ticks.NANOS;
        if (scans.nextTick() <= tick) {
            sense.at(0);
            scans.capture(tick - Math.floorMod(tick, Scans.PERIOD_TICKS), true);
        }
    }

    /** Sample the light sensors where the robot is now (a protocol client's {@code O}); snapshots show them. */
    void readLightNow(int[] out) {
        scanReady();
        end.sampleLight(movedTo, out);
        link.reportedLight(out);
    }

    /** A position move was started at {@code now}: the robot needs the engine from then on. */
    void positionMoveStarted(long now) {
        nextHardDue = StrictMath.min(nextHardDue, now);
        nextDue = StrictMath.min(nextDue, now);
    }

    /** The arena was edited: check clearance, caps and regions again. */
    void arenaEdited() {
        body.arenaEdited();
        proximity.arenaEdited();
        gripper.arenaEdited();
        capContacts.forget();
        coverage.arenaEdited();
    }

    // ------------------------------------------------------------------ the controller's side (through the link)

    /** @return what a controller does to this robot and reads from it, through the simulated serial link */
    public ControllerLink controls() {
        return controls;
    }

    /** A command went onto the link: the robot needs the engine when it arrives. */
    void commandQueued() {
        nextHardDue = StrictMath.min(nextHardDue, link.nextCommandDue());
        nextDue = StrictMath.min(nextDue, nextHardDue);
    }

    /** @return simulated time the robot has been moved to, ns */
    long movedTo() {
        return movedTo;
    }

    /** @param recorder hears this robot's commands and emergency stops from now on (see {@link Engine#record}) */
    void record(DriverRecorder recorder) {
        this.recorder = recorder;
        controls.record(recorder);
        camera.record(recorder);
    }

    /** Stop the wheels at once: the controller has ended, failed or been stopped (robot-link sends D,0,0). */
    public void emergencyStop() {
        if (recorder != null) {
            recorder.emergencyStop(id);
        }
        onBoard.speedMode();
        link.reset();
        if (onBoardLink != null) {
            onBoardLink.reset();
        }
        body.wheels().setSpeeds(0, 0);
    }

    /** @return the K213 linear vision turret, as the controller and a protocol client read it */
    public LinearCamera vision() {
        return camera;
    }

    /** @return the arena's width, mm */
    public double arenaWidth() {
        return world.arena().width();
    }

    /** @return the arena's height, mm (y up from its bottom edge) */
    public double arenaHeight() {
        return world.arena().height();
    }

    /** @return the gripper turret, as the controller and a protocol client see it */
    public GripperPort gripper() {
        return gripperPort;
    }

    // ------------------------------------------------------------------ on the robot (a protocol client)

    /** @return the robot as a protocol client drives it directly: motor modes, sensors read on demand, LEDs */
    public OnBoardControl onBoard() {
        return onBoard;
    }

    // ------------------------------------------------------------------ read-only views

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
        return body.x();
    }

    /** @return y, mm */
    public double y() {
        return body.y();
    }

    /** @return heading, degrees counter-clockwise from +x, in (−180, 180] */
    public double headingDeg() {
        return StrictMath.toDegrees(StrictMath.atan2(body.sin(), body.cos()));
    }

    /** @return the left speed in effect on the wheel, units */
    public int speedLeft() {
        return body.wheels().speedLeft();
    }

    /** @return the right speed in effect on the wheel, units */
    public int speedRight() {
        return body.wheels().speedRight();
    }

    /** @return the robot's own left position counter, pulses (not delayed by the link) */
    public int encoderLeft() {
        return DriveBody.pulses(body.encoderLeftExact());
    }

    /** @return the robot's own right position counter, pulses */
    public int encoderRight() {
        return DriveBody.pulses(body.encoderRightExact());
    }

    /** @return which side touches an obstacle */
    public Contact contact() {
        return body.contact();
    }

    /** @return true when the last tick's move was stopped by an obstacle */
    public boolean blocked() {
        return body.blocked();
    }

    /** @return number of times a move was stopped by an obstacle after moving freely */
    public int collisions() {
        return body.collisions();
    }

    /** @return path length of the robot's centre, mm */
    public double distanceTravelledMm() {
        return body.distanceMm();
    }

    /** @return percentage of the arena's floor cells the robot's body has covered */
    public double visitedPercent() {
        return coverage.visitedPercent();
    }

    /** @return the named regions the centre has entered, with the first entry's time in seconds, in arena order */
    public Map<String, Double> regionsEntered() {
        return coverage.regionsEntered();
    }

    /** @return the link timing this robot's controller lives with */
    public LinkTiming link() {
        return link.timing();
    }

    /** @return the settings this robot was built with */
    public Settings settings() {
        return settings;
    }

    /**
     * @param loop the controller's loop pause, counted from 0
     * @return how much longer than asked that pause lasts, ns (0 unless {@code wsu.loopTiming=desktop})
     */
    public long loopPauseExtraNanos(long loop) {
        return loopTiming == null ? 0 : LoopTiming.extraNanos(loopTiming.uniform(loop));
    }

    /** @return the settings in typed form */
    public RobotModel model() {
        return model;
    }

    /** @return the LEDs as a bit mask: bit 0 the lateral LED, bit 1 the front LED */
    public int leds() {
        return onBoard.leds();
    }

    /** Copy the values the controller sees at {@code now} into a snapshot's arrays. */
    void copyVisible(long now, int[] prox, int[] lightValues) {
        if (onBoardLink != null) {
            onBoardLink.copyLatest(prox, lightValues);
            return;
        }
        link.copyVisible(now, prox, lightValues);
    }
}
