package org.kheperasim.sim.engine.sensing;

import org.kheperasim.sim.engine.model.Ticks;


/**
 * The robot's own sensor scan. The Khepera's microcontroller reads its eight infrared channels,
 * reflected and ambient, every 20 ms, and whatever asks for a sensor (a poll reply, a program on
 * the robot) gets the latest scan. Scan k is the world at the start of tick 20k.
 *
 * <p>A scan is taken only when something will read it: the engine asks for scan k's pose at tick
 * 20k ({@link #capture}) when a reader is due in its window (every window while the link polls or
 * a protocol client drives the robot; the window of the next wake of a program on the robot), and
 * its values are computed when first read, then kept for the window. Each scan's noise is drawn at
 * its index, so an unread scan costs nothing and skipping one never shifts a draw.
 *
 * <p>Values computed after the capture are the values at the capture: the light sensors see only
 * walls and lamps, which only an edit changes ({@link #settle} first); the proximity sensors see
 * caps and other robots too, so a scan is computed at once where they may move within its window
 * (in a crowd, near a cap, the gripper moving) and otherwise left for the first read, the robot
 * being alone ({@link #settle} before it joins others).
 */
public final class Scans {
    /** The scan period: the Khepera manual's 20 ms (khepera-reference.md, "sensor refresh on the robot"). */
    static final long PERIOD_NANOS = 20_000_000L;
    /** Ticks per scan. */
    public static final long PERIOD_TICKS = PERIOD_NANOS / Ticks.NANOS;

    /** When scans are taken. */
    public enum Taking {
        /** Every window: a polling link or a protocol client may read any of them. */
        EVERY,
        /** Only the windows a program on the robot will read, as {@link #want} says. */
        WANTED
    }

    private final SamplePose sense;
    private final ProximitySensing proximity;
    private final LightSensing light;
    private final Coverage coverage;
    private final boolean lamps;

    private Taking taking = Taking.EVERY;
    /** The next scan to take, by its tick ({@link Long#MAX_VALUE}: none wanted). */
    private long nextTick;
    /** The scan taken last: its index (-1: none), pose, and values as far as computed. */
    private long index = -1;
    private final double[] pose = new double[4];
    private boolean heading;
    /** How many sensors the robot has. */
    private final int count;
    private final int[] prox;
    private final int[] lux;
    private boolean proxDone;
    private boolean luxDone;
    private final int[] ids = {};

    public Scans(SamplePose sense, ProximitySensing proximity, LightSensing light, Coverage coverage,
            boolean lamps, int count) {
        this.count = count;
        this.prox = new int[count];
        this.lux = new int[count];
        this.sense = sense;
        this.proximity = proximity;
        this.light = light;
        this.coverage = coverage;
        this.lamps = lamps;
    }

    /** @param nanos simulated time @return the index of the latest scan at that time */
    static long index(long nanos) {
        return Math.floorDiv(nanos, PERIOD_NANOS);
    }

    /** @param nanos simulated time @return the tick the latest scan at that time was taken at */
    static long tickOf(long nanos) {
        return index(nanos) * PERIOD_TICKS;
    }

    /** @param how when scans are taken from now on; {@code from} the robot's time, ns: the first at or after it */
    public void taking(Taking how, long from) {
        taking = how;
        if (how == Taking.EVERY) {
            long tick = Ticks.ceil(from);
            long first = (tick + PERIOD_TICKS - 1) / PERIOD_TICKS * PERIOD_TICKS;
            nextTick = first / PERIOD_TICKS <= index ? (index + 1) * PERIOD_TICKS : first;
        } else {
            nextTick = Long.MAX_VALUE;
        }
    }

    /**
     * A program on the robot will read the sensors at {@code readAt}: the scan of that window is taken
     * at its tick (unless taken already).
     *
     * @param readAt simulated time, ns ({@link Long#MAX_VALUE}: never)
     */
    public void want(long readAt) {
        if (taking != Taking.WANTED || readAt == Long.MAX_VALUE || index(readAt) <= index) {
            return;
        }
        nextTick = StrictMath.min(nextTick, tickOf(readAt));
    }

    /** @return true when scans are taken only where a program on the robot wants them */
    public boolean readsAtWakes() {
        return taking == Taking.WANTED;
    }

    /** @return the tick of the next scan to take ({@link Long#MAX_VALUE}: none wanted) */
    public long nextTick() {
        return nextTick;
    }

    /**
     * Take the scan of tick {@code tick}: the caller has put {@link SamplePose} at it.
     *
     * @param tick the scan's tick (a multiple of {@link #PERIOD_TICKS})
     * @param now whether the proximity values must be computed now: other robots or caps may move
     *     within the window, or the gripper does
     */
    public void capture(long tick, boolean now) {
        index = tick / PERIOD_TICKS;
        double[] p = sense.position();
        pose[0] = p[0];
        pose[1] = p[1];
        // The heading's trigonometry only where a sensor needs it: a lamp in the arena, something in reach.
        heading = lamps || !proximity.open(pose[0], pose[1]);
        if (heading) {
            p = sense.pose();
            pose[2] = p[2];
            pose[3] = p[3];
        }
        coverage.mark(pose[0], pose[1]);
        proxDone = false;
        luxDone = false;
        if (now) {
            computeProximity(false);
        }
        nextTick = taking == Taking.EVERY ? tick + PERIOD_TICKS : Long.MAX_VALUE;
    }

    /** The robot joins others, or the arena is edited: compute what was left for a later read now. */
    public void settle() {
        if (index >= 0 && !proxDone) {
            computeProximity(true);
        }
        if (index >= 0 && !luxDone) {
            computeLight();
        }
    }

    /**
     * @param now simulated time, ns: the scan read is the latest at that time
     * @param out receives the eight proximity values, 0..1023, higher = nearer
     */
    public void proximity(long now, int[] out) {
        check(now);
        if (!proxDone) {
            computeProximity(true);
        }
        System.arraycopy(prox, 0, out, 0, count);
    }

    /**
     * @param now simulated time, ns: the scan read is the latest at that time
     * @param out receives the eight light values, 0..1023, lower = brighter
     */
    public void light(long now, int[] out) {
        check(now);
        if (!luxDone) {
            computeLight();
        }
        System.arraycopy(lux, 0, out, 0, count);
    }

    /**
     * @return sensor {@code i}'s proximity value in the latest scan at {@code now} (a program on the robot reads it)
     */
    public int proximityOf(long now, int i) {
        check(now);
        if (!proxDone) {
            computeProximity(true);
        }
        return prox[i];
    }

    /** @return sensor {@code i}'s light value in the latest scan at {@code now} */
    public int lightOf(long now, int i) {
        check(now);
        if (!luxDone) {
            computeLight();
        }
        return lux[i];
    }

    /** The values of the scan taken last (for a snapshot: what a program on the robot reads now). */
    public void latest(int[] proxOut, int[] lightOut) {
        if (!proxDone) {
            computeProximity(true);
        }
        if (!luxDone) {
            computeLight();
        }
        System.arraycopy(prox, 0, proxOut, 0, count);
        System.arraycopy(lux, 0, lightOut, 0, count);
    }

    /**
     * @param now simulated time, ns
     * @return the index of the latest scan then, the key of {@link LightSensing#fillDark} for a dark one
     */
    public long indexAt(long now) {
        check(now);
        return index;
    }

    /** @return the index of the scan taken last (-1: none) */
    long last() {
        return index;
    }

    private void check(long now) {
        long k = index(now);
        if (k != index) {
            throw new IllegalStateException("scan " + k + " (at " + now + " ns) was not taken; the last was " + index);
        }
    }

    /** @param alone the robot was alone since the capture: no other robot in its sensors' reach */
    private void computeProximity(boolean alone) {
        if (alone) {
            proximity.scope(ids, 0, 0);
        }
        try {
            if (!heading) {
                if (proximity.open(pose[0], pose[1])) {
                    proximity.sampleOpen(index, prox);
                    proxDone = true;
                    return;
                }
                throw new IllegalStateException("scan " + index + " found something in reach without its heading");
            }
            if (proximity.open(pose[0], pose[1])) {
                proximity.sampleOpen(index, prox);
            } else {
                proximity.sampleNear(pose[0], pose[1], pose[2], pose[3], index, prox);
            }
            proxDone = true;
        } finally {
            if (alone) {
                proximity.scope(null, 0, 0);
            }
        }
    }

    private void computeLight() {
        if (!lamps) {
            light.fillDark(index, lux);
        } else {
            light.sample(pose[0], pose[1], pose[2], pose[3], index, lux);
        }
        luxDone = true;
    }
}
