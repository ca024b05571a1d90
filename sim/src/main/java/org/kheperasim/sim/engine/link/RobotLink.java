package org.kheperasim.sim.engine.link;

import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.link.timing.PollStep;
import org.kheperasim.sim.engine.model.Ticks;
import org.kheperasim.sim.engine.sensing.SensorPlacement;

/**
 * The serial link between a controller and its simulated robot, as robot-link drives a real one.
 *
 * <p>Commands: like robot-link, a speed command goes out only when the asked speeds differ from
 * those last sent, one command on the line at a time; speeds asked for while the line is busy
 * replace each other and the latest goes out next. A command acts when its characters and the
 * robot's turnaround have passed.
 *
 * <p>Polling: the cycle N, O, H runs back to back. Each step's values are sampled on the robot when
 * it has read the command and turned around, and become visible to the controller when the reply's
 * last character has arrived; a reply is as long as the numbers it carries, so the next exchange
 * starts earlier after short values (see {@link LinkTiming#replyChars}).
 */
public final class RobotLink {
    /** A command's acknowledgement, e.g. {@code d} CR LF. */
    private static final int ACK_CHARS = 3;
    private static final PollStep[] CYCLE = LinkTiming.POLL_CYCLE.toArray(new PollStep[0]);
    private static final int PROXIMITY = LinkTiming.POLL_CYCLE.indexOf(PollStep.PROXIMITY);
    private static final int LIGHT = LinkTiming.POLL_CYCLE.indexOf(PollStep.LIGHT);
    private static final int ENCODERS = LinkTiming.POLL_CYCLE.indexOf(PollStep.ENCODERS);

    /** What the link acts on: the robot at its end. */
    interface Robot {
        void applySpeeds(long now, int left, int right);

        void applyCounters(int left, int right);

        void applyArm(long now, int position);

        void applyFingers(long now, boolean closed);

        /** The proximity values of the latest scan at {@code now} into {@code out}. */
        void sampleProximity(long now, int[] out);

        /** The light values of the latest scan at {@code now} into {@code out}. */
        void sampleLight(long now, int[] out);

        /**
         * The light values of the latest scan at {@code now} for the poll cycle: into {@code out}, or,
         * when the reply's length is known without the values (darkness), later ({@link #fillLight}).
         *
         * @return -1 when {@code out} holds the values, else the scan's key for {@link #fillLight}
         */
        long pollLight(long now, int[] out);

        /** @return the reply characters of the eight values of a deferred light sample */
        int deferredLightChars();

        /** The values of the deferred light sample {@code key}, the same as if taken at once. */
        void fillLight(long key, int[] out);

        /** @return the robot's left counter for the sample being taken, pulses */
        int sampleCounterLeft();

        /** @return the robot's right counter for the sample being taken, pulses */
        int sampleCounterRight();
    }

    private final LinkTiming timing;
    /** How many sensor values a proximity or light reply carries. */
    private final int sensors;
    private final Robot robot;
    private final CommandQueue commands = new CommandQueue();
    private long lineFreeAt;
    private int askedLeft;
    private int askedRight;
    private int sentLeft;
    private int sentRight;
    private boolean speedPending;
    /** Proximity replies taken so far: the poll cycles run. */
    private long proximityReplies;

    // The poll cycle: the step whose sample comes next, and when. Each step's last sample waits in
    // `sampled` until its reply has arrived (`deliverAt`); it is delivered lazily, when someone looks
    // at or after that time, or when the step's next sample is taken.
    private boolean polling = true;
    private int step;
    private long sampleAt;
    private final int[][] sampled = new int[CYCLE.length][];
    private final int[][] visible = new int[CYCLE.length][];
    private final long[] deliverAt = new long[CYCLE.length];
    private final boolean[] pending = new boolean[CYCLE.length];
    /** A step's sample (and its visible values) whose values are still to be computed: its key, or -1. */
    private final long[] sampledKey = new long[CYCLE.length];
    private final long[] visibleKey = new long[CYCLE.length];

    /** Wire time of a poll step's command and turnaround, per step; and of a line of n characters. */
    private final long[] commandNanos = new long[CYCLE.length];
    private final long[] lineNanos = new long[64];

    public RobotLink(LinkTiming timing, Robot robot, int sensors) {
        this.sensors = sensors;
        this.timing = timing;
        this.robot = robot;
        for (int k = 0; k < CYCLE.length; k++) {
            commandNanos[k] = timing.commandNanos(CYCLE[k]);
        }
        for (int n = 0; n < lineNanos.length; n++) {
            lineNanos[n] = timing.wireNanos(n);
        }
        for (int k = 0; k < CYCLE.length; k++) {
            int n = CYCLE[k] == PollStep.ENCODERS ? 2 : sensors;
            sampled[k] = new int[n];
            visible[k] = new int[n];
            sampledKey[k] = -1;
            visibleKey[k] = -1;
        }
    }

    /** robot-link primes every value before it starts the controller; so does the simulator (from scan 0). */
    public void prime() {
        for (int k = 0; k < CYCLE.length; k++) {
            take(CYCLE[k], 0, visible[k]);
        }
        step = 0;
        sampleAt = commandNanos[0];
    }

    /** Stop polling (a protocol client polls the robot itself). */
    public void stopPolling() {
        polling = false;
    }

    /**
     * A protocol client read the proximity sensors on the robot itself ({@code N}): with polling
     * stopped, these are the values the robot last reported, and what a snapshot shows.
     */
    public void reportedProximity(int[] values) {
        reported(PROXIMITY, values);
    }

    /** As {@link #reportedProximity}, for the light sensors ({@code O}). */
    public void reportedLight(int[] values) {
        reported(LIGHT, values);
    }

    private void reported(int k, int[] values) {
        System.arraycopy(values, 0, visible[k], 0, visible[k].length);
        visibleKey[k] = -1;
        pending[k] = false;
    }

    // ------------------------------------------------------------------ commands

    /** The controller asks for wheel speeds at {@code now}. */
    public void commandSpeeds(long now, int left, int right) {
        askedLeft = left;
        askedRight = right;
        speedPending = left != sentLeft || right != sentRight;
        if (speedPending && now >= lineFreeAt) {
            sendSpeeds(now);
        }
    }

    /**
     * @return false when {@link #commandSpeeds} with these arguments would leave the link exactly as it
     *     is: the speeds are those asked last, and no pending command would go out now (a pending
     *     command always means the asked speeds differ from those sent)
     */
    public boolean speedsWouldChange(long now, int left, int right) {
        return left != askedLeft || right != askedRight || (speedPending && now >= lineFreeAt);
    }

    private void sendSpeeds(long start) {
        long delay = timing.speedCommandDelayNanos(askedLeft, askedRight);
        commands.add(start + delay, CommandQueue.SPEED, askedLeft, askedRight);
        lineFreeAt = start + delay + timing.wireNanos(ACK_CHARS);
        sentLeft = askedLeft;
        sentRight = askedRight;
        speedPending = false;
    }

    /** The controller sets the position counters ({@code G}); it waits its turn on the line. */
    public void commandPositions(long now, int left, int right) {
        long start = StrictMath.max(now, lineFreeAt);
        long delay = timing.setPositionDelayNanos(left, right);
        commands.add(start + delay, CommandQueue.POSITION, left, right);
        lineFreeAt = start + delay + timing.wireNanos(ACK_CHARS);
    }

    /** The controller moves the arm ({@code T,1,E,pos}), 0..255. */
    public void commandArm(long now, int position) {
        int target = StrictMath.max(0, StrictMath.min(255, position));
        queueTurret(now, CommandQueue.ARM, target, "T,1,E," + target, 3);
    }

    /** The controller opens or closes the fingers ({@code T,1,D,0|1}). */
    public void commandFingers(long now, boolean closed) {
        int c = closed ? 1 : 0;
        queueTurret(now, CommandQueue.FINGERS, c, "T,1,D," + c, 3);
    }

    private void queueTurret(long now, int type, int value, String command, int replyPayload) {
        long start = StrictMath.max(now, lineFreeAt);
        // The command line and CR, then the reply: "t,1," + payload + CR LF.
        long delay = timing.wireNanos(command.length() + 1) + timing.turnaroundNanos();
        commands.add(start + delay, type, value, 0);
        lineFreeAt = start + delay + timing.wireNanos(4 + replyPayload + 2);
    }

    /** Everything in flight is dropped and the speeds are zero (robot-link sends {@code D,0,0}). */
    public void reset() {
        askedLeft = 0;
        askedRight = 0;
        commands.clear();
        speedPending = false;
        sentLeft = 0;
        sentRight = 0;
    }

    /** Speeds set on the robot itself (a protocol client): what the controller's side last asked. */
    public void asked(int left, int right) {
        askedLeft = left;
        askedRight = right;
    }

    // ------------------------------------------------------------------ time

    /** Apply the commands that have arrived by {@code now}, and send a pending speed command when the line is free. */
    public void commandsDue(long now) {
        if (speedPending && lineFreeAt <= now) {
            sendSpeeds(lineFreeAt);
        }
        while (commands.headTime() <= now) {
            int type = commands.headType();
            int a = commands.headA();
            int b = commands.headB();
            commands.pop();
            switch (type) {
                case CommandQueue.SPEED -> robot.applySpeeds(now, a, b);
                case CommandQueue.POSITION -> robot.applyCounters(a, b);
                case CommandQueue.ARM -> robot.applyArm(now, a);
                case CommandQueue.FINGERS -> robot.applyFingers(now, a == 1);
                default -> throw new IllegalStateException("command type " + type);
            }
        }
    }

    /** @return when the next command arrives or a pending one can go out, ns ({@link Long#MAX_VALUE}: never) */
    public long nextCommandDue() {
        long t = commands.headTime();
        return speedPending && lineFreeAt < t ? lineFreeAt : t;
    }

    /**
     * Take the poll cycle's samples due by the tick at {@code now}, if any: the proximity and light
     * replies carry the robot's latest scan then, the counters are read where the robot is at
     * {@code now}. Call it for every tick at which {@link #nextPollDue} falls, in order.
     */
    public void pollDue(long now) {
        while (polling && sampleAt <= now) {
            int k = step;
            if (pending[k]) {
                deliver(k);
            }
            // The reply is as long as the values it carries.
            int[] values = sampled[k];
            int chars;
            if (k == PROXIMITY) {
                robot.sampleProximity(now, values);
                chars = readingsReplyChars(values);
                proximityReplies++;
            } else if (k == LIGHT) {
                sampledKey[k] = robot.pollLight(now, values);
                chars = sampledKey[k] >= 0 ? 1 + sensors + 2 + robot.deferredLightChars() : readingsReplyChars(values);
            } else {
                take(CYCLE[k], now, values);
                chars = LinkTiming.replyChars(CYCLE[k], values);
            }
            deliverAt[k] = sampleAt + (chars < lineNanos.length ? lineNanos[chars] : timing.wireNanos(chars));
            pending[k] = true;
            step = k + 1 == CYCLE.length ? 0 : k + 1;
            sampleAt = deliverAt[k] + commandNanos[step];
        }
    }

    /** @return when the poll cycle's next sample is taken, ns ({@link Long#MAX_VALUE}: not polling) */
    public long nextPollDue() {
        return polling ? sampleAt : Long.MAX_VALUE;
    }

    /** {@link LinkTiming#replyChars} of eight sensor readings (0..1023), counted without a loop per digit. */
    private static int readingsReplyChars(int[] values) {
        int chars = 1 + values.length + 2;
        for (int v : values) {
            if (v < 0 || v > 9999) {
                return LinkTiming.replyChars(PollStep.PROXIMITY, values);
            }
            chars += SensorPlacement.digits(v);
        }
        return chars;
    }

    /** Take a step's sample on the robot at {@code now}. */
    private void take(PollStep s, long now, int[] out) {
        switch (s) {
            case PROXIMITY -> robot.sampleProximity(now, out);
            case LIGHT -> robot.sampleLight(now, out);
            case ENCODERS -> {
                out[0] = robot.sampleCounterLeft();
                out[1] = robot.sampleCounterRight();
            }
            default -> throw new IllegalStateException("poll step " + s);
        }
    }

    private void deliver(int k) {
        visibleKey[k] = sampledKey[k];
        if (visibleKey[k] < 0) {
            // The sample's array becomes the visible one; the old visible one takes the next sample.
            int[] delivered = sampled[k];
            sampled[k] = visible[k];
            visible[k] = delivered;
        }
        pending[k] = false;
    }

    /**
     * @param step a poll step
     * @param now  a controller's simulated time, ns
     * @return true when a read at {@code now} delivers the step's pending sample: a controller whose
     *     calls reach past the tick the engine is at sees a reply before the engine's own tick does, and
     *     from then on so does everything else (a snapshot at the engine's tick)
     */
    public boolean readDelivers(PollStep step, long now) {
        int k = step == PollStep.PROXIMITY ? PROXIMITY : step == PollStep.LIGHT ? LIGHT : ENCODERS;
        return pending[k] && deliverAt[k] <= now - Math.floorMod(now, Ticks.NANOS);
    }

    /**
     * The values of step k as the controller sees them at {@code now}: delivered once the reply is in by the tick's
     * start.
     */
    private int[] seen(int k, long now) {
        if (pending[k] && deliverAt[k] <= now - Math.floorMod(now, Ticks.NANOS)) {
            deliver(k);
        }
        if (visibleKey[k] >= 0) {
            robot.fillLight(visibleKey[k], visible[k]);
            visibleKey[k] = -1;
        }
        return visible[k];
    }

    // ------------------------------------------------------------------ what the controller sees

    /** @param now the controller's simulated time, ns @param i sensor index @return the proximity value it sees */
    public int visibleProximity(long now, int i) {
        return seen(PROXIMITY, now)[i];
    }

    /** @param now simulated time, ns @param i sensor index @return the light value the controller sees */
    public int visibleLight(long now, int i) {
        return seen(LIGHT, now)[i];
    }

    /** @param now simulated time, ns @return the left counter the controller sees, pulses */
    public int visibleCounterLeft(long now) {
        return seen(ENCODERS, now)[0];
    }

    /** @param now simulated time, ns @return the right counter the controller sees, pulses */
    public int visibleCounterRight(long now) {
        return seen(ENCODERS, now)[1];
    }

    /** Copy the values the controller sees at {@code now} into a snapshot's arrays. */
    public void copyVisible(long now, int[] prox, int[] light) {
        System.arraycopy(seen(PROXIMITY, now), 0, prox, 0, sensors);
        System.arraycopy(seen(LIGHT, now), 0, light, 0, sensors);
    }

    /** @return the proximity replies taken so far (one per poll cycle) */
    public long proximityReplies() {
        return proximityReplies;
    }

    public int askedLeft() {
        return askedLeft;
    }

    public int askedRight() {
        return askedRight;
    }

    public LinkTiming timing() {
        return timing;
    }
}
