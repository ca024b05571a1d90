package org.kheperasim.link.robot;

import java.util.Queue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;
import org.kheperasim.api.ArmPosition;
import org.kheperasim.api.GripperState;
import org.kheperasim.api.IrSensor;
import org.kheperasim.api.spi.Mount;
import org.kheperasim.api.spi.RobotPort;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.Reply;
import org.kheperasim.link.protocol.TurretCommand;
import org.kheperasim.link.protocol.dialect.Dialect;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.session.SessionException;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.link.timing.PollStep;

/**
 * A real Khepera behind the student API. A poll thread runs the cycle of {@link LinkTiming#POLL_CYCLE}
 * ({@code N}, {@code O}, {@code H}, then the gripper's barrier and resistivity when one is fitted) as
 * fast as the link allows, in the session's {@link Dialect} (on an e-puck: {@code N}, {@code O}, {@code Q},
 * speeds by its {@code D} in steps/s, no turrets), and the API reads the values it last stored. Before each exchange it
 * sends what the controller changed: a {@code D} when the asked speeds differ from those last sent,
 * and queued position-counter and gripper commands. So a motor command waits at most one exchange.
 *
 * <p>The K213 vision turret is not polled (its image is a long reply: about 60 ms at 38400 baud): a
 * controller's read goes onto the line between two exchanges of the cycle, and the controller waits
 * for the reply. A robot that refuses the turret's commands has none: a warning, once, and images
 * of zeros from then on.
 *
 * <p>{@link #stop()} ends polling and sends {@code D,0,0} (and parks the gripper if asked); after it,
 * nothing more is sent, so {@code D,0,0} is the last thing the robot hears.
 */
public final class RobotBackend implements RobotPort {
    private static final System.Logger LOG = System.getLogger(RobotBackend.class.getName());

    private final Session session;
    private final RobotSettings settings;
    private final Dialect dialect;
    private final Consumer<String> console;
    private final Queue<Command> queued = new ConcurrentLinkedQueue<>();
    /** Reads of the vision turret a controller waits for, served by the poll thread in order. */
    private final Queue<VisionRead> visionReads = new ConcurrentLinkedQueue<>();
    private volatile boolean visionRefused;
    private final CountDownLatch firstCycle = new CountDownLatch(1);
    private final Thread poller;

    private volatile int[] proximity = new int[8];
    private volatile int[] light = new int[8];
    private volatile int leftPosition;
    private volatile int rightPosition;
    private volatile int askedLeft;
    private volatile int askedRight;
    private volatile long wantedSpeeds = pack(0, 0);
    private volatile long sentSpeeds = Long.MIN_VALUE;
    private long foreignSeen;
    /** Boot banners already handled, and what the controller's counters carry over a reboot. */
    private long bootsSeen;
    private long bootsAtCounters;
    private int offsetLeft;
    private int offsetRight;
    private volatile boolean objectPresent;
    private volatile int resistivity;
    private volatile GripperState fingers = GripperState.OPEN;
    private volatile ArmPosition armRest = ArmPosition.UP;
    private volatile ArmPosition armTarget = ArmPosition.UP;
    private volatile long armArrivesNanos;
    private volatile boolean gripperPolled;
    private volatile boolean clampReported;
    private volatile boolean gripperWarned;
    private volatile boolean visionWarned;

    private volatile boolean running;
    private volatile boolean stopped;
    private volatile SessionException failure;
    private volatile long cycles;
    private volatile long startNanos;

    /** @return when the run started, {@link System#nanoTime()}; 0 before: the zero of its samples' times */
    public long startNanos() {
        return startNanos;
    }
    private volatile long endNanos;
    private volatile Consumer<Sample> sampleListener = s -> { };
    private final Object stopLock = new Object();
    private Boolean stopAcknowledged;

    /**
     * @param session an open session
     * @param settings speed clamp and gripper
     * @param console where controller messages and warnings go, one line each
     */
    public RobotBackend(Session session, RobotSettings settings, Consumer<String> console) {
        this.session = session;
        this.dialect = session.dialect();
        this.settings = settings.checkFor(dialect);
        this.console = console;
        this.gripperPolled = settings.gripper();
        this.visionRefused = !dialect.turrets();
        this.poller = new Thread(this::poll, "khepera-poll");
        poller.setDaemon(true);
    }

    /** @param listener called on the poll thread after every cycle (a recorder) */
    public void onSample(Consumer<Sample> listener) {
        sampleListener = listener;
    }

    /**
     * Start polling and wait for the first complete cycle, so a controller never sees unread values.
     *
     * @param timeoutMillis how long to wait for the first cycle, ms
     * @throws SessionException when the first cycle fails (the robot does not answer)
     */
    public void start(long timeoutMillis) throws SessionException, InterruptedException {
        running = true;
        startNanos = System.nanoTime();
        poller.start();
        if (!firstCycle.await(timeoutMillis, TimeUnit.MILLISECONDS) && failure == null) {
            throw new SessionException(SessionException.Kind.NO_REPLY, dialect.readProximity(),
                    "the first poll cycle did not finish in " + timeoutMillis + " ms on "
                            + session.link().describe(), null);
        }
        if (failure != null) {
            throw failure;
        }
    }

    private void poll() {
        try {
            while (running) {
                for (PollStep step : LinkTiming.POLL_CYCLE) {
                    if (!running) {
                        return;
                    }
                    sendChanges();
                    read(step);
                }
                if (gripperPolled) {
                    sendChanges();
                    pollGripper();
                }
                cycles++;
                firstCycle.countDown();
                sampleListener.accept(new Sample(System.nanoTime() - startNanos, proximity, light, leftPosition,
                        rightPosition, unpackLeft(sentSpeeds), unpackRight(sentSpeeds)));
            }
        } catch (SessionException e) {
            failure = e;
            running = false;
            firstCycle.countDown();
        } catch (RuntimeException e) {
            failure = new SessionException(SessionException.Kind.LINK_LOST, null, "the poll loop failed: " + e, e);
            running = false;
            firstCycle.countDown();
        }
    }

    private void read(PollStep step) throws SessionException {
        switch (step) {
            case PROXIMITY -> proximity = session.exchange(dialect.readProximity()).ints();
            case LIGHT -> light = session.exchange(dialect.readLight()).ints();
            case ENCODERS -> {
                int[] v = session.exchange(dialect.readCounters()).ints();
                long boots = session.boots();
                if (boots != bootsAtCounters) {
                    // The robot rebooted since the counters were last read (perhaps during this very
                    // exchange): they restarted at 0, so carry on from where the controller was.
                    bootsAtCounters = boots;
                    offsetLeft = leftPosition - v[0];
                    offsetRight = rightPosition - v[1];
                }
                leftPosition = v[0] + offsetLeft;
                rightPosition = v[1] + offsetRight;
            }
        }
    }

    private void pollGripper() throws SessionException {
        try {
            Reply barrier = session.exchange(Command.Turret.gripper(new TurretCommand.Barrier()));
            objectPresent = barrier.intValue(0) != 0;
            Reply res = session.exchange(Command.Turret.gripper(new TurretCommand.Resistivity()));
            resistivity = res.intValue(0);
        } catch (SessionException e) {
            if (e.kind() != SessionException.Kind.REFUSED) {
                throw e;
            }
            gripperPolled = false;
            console.accept("warning: the robot refused a gripper command (" + e.getMessage()
                    + "); gripper polling is off. Is the gripper turret fitted?");
        }
    }

    /** Send the changed speeds, then queued commands. Runs on the poll thread. */
    private void sendChanges() throws SessionException {
        long boots = session.boots();
        if (boots != bootsSeen) {
            bootsSeen = boots;
            console.accept("warning: the robot rebooted during the run (its boot banner arrived on "
                    + session.link().describe() + "): it had stopped its wheels and restarted its position counters"
                    + " at 0. The run goes on: the speeds are sent again, and the positions the controller reads"
                    + " continue from where they were. Check the battery and the cable.");
        }
        long foreign = session.foreignLines();
        if (foreign != foreignSeen) {
            // A banner (a reset robot has stopped its wheels) or noise: say the speeds again.
            foreignSeen = foreign;
            sentSpeeds = Long.MIN_VALUE;
        }
        long wanted = wantedSpeeds;
        if (wanted != sentSpeeds) {
            session.exchange(dialect.setSpeeds(unpackLeft(wanted), unpackRight(wanted)));
            sentSpeeds = wanted;
        }
        Command c;
        while ((c = queued.poll()) != null) {
            session.exchange(c);
        }
        VisionRead v;
        while ((v = visionReads.poll()) != null) {
            serveVision(v);
        }
    }

    /** A controller's read of the vision turret, waiting for its reply. */
    private record VisionRead(TurretCommand body, CompletableFuture<int[]> reply) {
    }

    private void serveVision(VisionRead v) throws SessionException {
        if (visionRefused) {
            v.reply().complete(blank(v.body()));
            return;
        }
        try {
            v.reply().complete(session.exchange(Command.Turret.vision(v.body())).ints());
        } catch (SessionException e) {
            if (e.kind() != SessionException.Kind.REFUSED) {
                v.reply().completeExceptionally(e);
                throw e;
            }
            visionRefused = true;
            console.accept("warning: the robot refused a vision turret command (" + e.getMessage()
                    + "); is the K213 vision turret fitted? The controller's images are all 0 from now on");
            v.reply().complete(blank(v.body()));
        }
    }

    /** What a read of a turret that is not there gives: an image of zeros, or pixel 0. */
    private static int[] blank(TurretCommand body) {
        return new int[body.replyValueCount()];
    }

    /**
     * Stop the robot: end polling, then send {@code D,0,0} (park the gripper and send {@code D,0,0}
     * again if asked). Safe to call from any thread, more than once; the first call does the work,
     * later calls wait for it.
     *
     * @return true when the robot acknowledged the stop, false when it was sent without an answer
     *     (or could not be sent: the link has gone)
     */
    public boolean stop() {
        synchronized (stopLock) {
            if (stopAcknowledged != null) {
                return stopAcknowledged;
            }
            stopped = true;
            running = false;
            endNanos = System.nanoTime();
            if (Thread.currentThread() != poller) {
                try {
                    poller.join(5000);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
            VisionRead v;
            while ((v = visionReads.poll()) != null) {
                v.reply().completeExceptionally(new ControllerStoppedError());
            }
            boolean ok = sendStop();
            if (settings.parkGripperOnStop() && settings.gripper() && !session.isLost()) {
                try {
                    session.exchange(Command.Turret.gripper(new TurretCommand.Fingers(false)));
                    session.exchange(Command.Turret.gripper(new TurretCommand.Arm(settings.armUp())));
                } catch (SessionException e) {
                    console.accept("warning: could not park the gripper: " + e.getMessage());
                }
                ok = sendStop();
            }
            stopAcknowledged = ok;
            return ok;
        }
    }

    private boolean sendStop() {
        if (!session.isLost()) {
            try {
                session.exchange(dialect.setSpeeds(0, 0));
                sentSpeeds = pack(0, 0);
                return true;
            } catch (SessionException e) {
                // Say it anyway, below: the robot may hear without being heard.
                LOG.log(System.Logger.Level.WARNING, "D,0,0 was not acknowledged (" + e.getMessage()
                        + "); sending it once more without waiting");
            }
        }
        session.sendBlind(dialect.setSpeeds(0, 0));
        return false;
    }

    /** @return why polling ended early (the link failed), or null */
    public SessionException failure() {
        return failure;
    }

    /** @return true while the poll loop runs */
    public boolean isPolling() {
        return running && poller.isAlive();
    }

    /** @return complete poll cycles per second since polling started */
    public double pollRateHz() {
        long elapsed = (endNanos != 0 ? endNanos : System.nanoTime()) - startNanos;
        return elapsed <= 0 ? 0 : cycles * 1e9 / elapsed;
    }

    /** @return complete poll cycles so far */
    public long cycles() {
        return cycles;
    }

    /** @return the session */
    public Session session() {
        return session;
    }

    private static long pack(int left, int right) {
        return ((long) left << 32) | (right & 0xffffffffL);
    }

    private static int unpackLeft(long packed) {
        return packed == Long.MIN_VALUE ? 0 : (int) (packed >> 32);
    }

    private static int unpackRight(long packed) {
        return packed == Long.MIN_VALUE ? 0 : (int) packed;
    }

    // ------------------------------------------------------------------ RobotPort

    /**
     * After the stop, a controller still reading sensors or sleeping is unwound (see {@link ControllerStoppedError}).
     */
    private void unwindIfStopped() {
        if (stopped && Thread.currentThread() != poller) {
            throw new ControllerStoppedError();
        }
    }

    @Override
    public int proximity(int index) {
        unwindIfStopped();
        return proximity[index];
    }

    @Override
    public int ambientLight(int index) {
        unwindIfStopped();
        return light[index];
    }

    @Override
    public void setSpeeds(int left, int right) {
        askedLeft = left;
        askedRight = right;
        int max = settings.maxSpeed();
        int l = Math.max(-max, Math.min(max, left));
        int r = Math.max(-max, Math.min(max, right));
        if ((l != left || r != right) && !clampReported) {
            clampReported = true;
            console.accept("note: speeds (" + left + ", " + right + ") were limited to ±" + max
                    + " units by the speed clamp (--max-speed); this is reported once");
        }
        if (!stopped) {
            wantedSpeeds = pack(l, r);
        }
    }

    @Override
    public int leftSpeed() {
        return askedLeft;
    }

    @Override
    public int rightSpeed() {
        return askedRight;
    }

    @Override
    public int leftPosition() {
        unwindIfStopped();
        return leftPosition;
    }

    @Override
    public int rightPosition() {
        unwindIfStopped();
        return rightPosition;
    }

    @Override
    public void setPositions(int left, int right) {
        if (!stopped) {
            queued.add(dialect.setCounters(left, right));
        }
    }

    private boolean gripperUsable() {
        if (settings.gripper()) {
            return true;
        }
        if (!gripperWarned) {
            gripperWarned = true;
            console.accept("warning: the controller uses the gripper, but robot-link was started without --gripper;"
                    + " gripper commands are not sent");
        }
        return false;
    }

    @Override
    public void setArmDown(boolean down) {
        ArmPosition position = down ? ArmPosition.DOWN : ArmPosition.UP;
        if (stopped || !gripperUsable()) {
            return;
        }
        settleArm();
        if (position != armTarget) {
            armTarget = position;
            armArrivesNanos = System.nanoTime() + settings.armTravelMillis() * 1_000_000L;
            queued.add(Command.Turret.gripper(new TurretCommand.Arm(
                    position == ArmPosition.UP ? settings.armUp() : settings.armDown())));
        }
    }

    private void settleArm() {
        if (armRest != armTarget && System.nanoTime() >= armArrivesNanos) {
            armRest = armTarget;
        }
    }

    @Override
    public boolean armDown() {
        settleArm();
        return armRest == ArmPosition.DOWN;
    }

    @Override
    public boolean armMoving() {
        settleArm();
        return armRest != armTarget;
    }

    @Override
    public void setFingersClosed(boolean closed) {
        GripperState state = closed ? GripperState.CLOSED : GripperState.OPEN;
        if (stopped || !gripperUsable()) {
            return;
        }
        if (state != fingers) {
            fingers = state;
            queued.add(Command.Turret.gripper(new TurretCommand.Fingers(state == GripperState.CLOSED)));
        }
    }

    @Override
    public boolean fingersClosed() {
        return fingers == GripperState.CLOSED;
    }

    @Override
    public boolean objectPresent() {
        return objectPresent;
    }

    @Override
    public int resistivity() {
        return resistivity;
    }

    @Override
    public int[] visionImage() {
        return readVision(new TurretCommand.Image());
    }

    @Override
    public int visionBrightest() {
        return readVision(new TurretCommand.BrightestPixel())[0];
    }

    @Override
    public int visionDarkest() {
        return readVision(new TurretCommand.DarkestPixel())[0];
    }

    /** Hand a turret read to the poll thread and wait for its reply; unwound when the run stops. */
    private int[] readVision(TurretCommand body) {
        unwindIfStopped();
        if (!dialect.turrets() && !visionWarned) {
            visionWarned = true;
            console.accept("warning: the controller reads the vision turret, but the " + dialect.robot()
                    + " takes no turret; its images are all 0");
        }
        if (visionRefused) {
            return blank(body);
        }
        VisionRead read = new VisionRead(body, new CompletableFuture<>());
        visionReads.add(read);
        while (true) {
            try {
                return read.reply().get(50, TimeUnit.MILLISECONDS);
            } catch (TimeoutException e) {
                if (stopped || !running) {
                    // The poll thread has gone (a stop, a lost link): nobody will answer.
                    throw new ControllerStoppedError();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new ControllerStoppedError();
            } catch (ExecutionException e) {
                throw new ControllerStoppedError();
            }
        }
    }

    @Override
    public String option(String key) {
        return settings.options().get(key);
    }

    @Override
    public void sleep(long millis) throws InterruptedException {
        unwindIfStopped();
        Thread.sleep(millis);
    }

    @Override
    public void message(String text) {
        console.accept(text);
    }

    /**
     * @return the Khepera's sensor poses (the student API's {@code IrSensor}); this backend reports the
     *     Khepera's shape whatever the dialect (the e-puck's sensor poses are not known to robot-link)
     */
    @Override
    public Mount mount(int index) {
        IrSensor s = IrSensor.of(index);
        return new Mount(s.name(), s.xMm(), s.yMm(), s.headingDeg());
    }
}
