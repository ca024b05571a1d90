package org.kheperasim.sim.engine;

import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.engine.model.Ticks;
import org.kheperasim.sim.engine.space.Bodies;

/**
 * Moves every robot through a stretch of ticks with nothing due (no command, controller, noise
 * redraw or snapshot), each as cheaply as it can:
 *
 * <ul>
 *   <li>a robot that no other robot can reach during the stretch (neither touch nor see, nor be
 *       seen, even if both drive straight at each other) moves on its own: it glides as far as its
 *       own clearance allows, and steps a tick with contact handling where it must, its scans and
 *       poll samples taken on the way (exactly what a lone robot does);</li>
 *   <li>robots that may see each other move on their own between their scans, each scan seeing
 *       the others where they are at its tick, and those that may touch each other a tick at a
 *       time, in robot order ({@link Crowd});</li>
 *   <li>when a robot may push or carry a cap, or its gripper moves, every robot moves a tick at a
 *       time, in robot order, so each sees the others and the caps where they are at that tick: a
 *       cap may jump by as much as a part newly overlaps it (fingers lowered beside it, a grip
 *       closing, caps overlapping in a row), so no distance bounds who may see it move.</li>
 * </ul>
 * So a robot near a wall no longer makes a far-away one step every tick, and the cost of a swarm
 * grows with the robots that are near each other, not with all of them.
 */
final class Motion {
    private final List<SimRobot> robots;
    private final Bodies bodies;
    private final List<SimRobot> together = new ArrayList<>();
    private final List<SimRobot> lone = new ArrayList<>();
    private final Crowd crowd;
    /** Moves the robots on their own on two threads, or null: on the turn holder's alone. */
    private SplitWork split;
    private long stretchStart;
    private long stretchTicks;

    Motion(List<SimRobot> robots, Bodies bodies) {
        this.robots = robots;
        this.bodies = bodies;
        this.crowd = new Crowd(robots, bodies);
    }

    /** @param split splits the moves of robots on their own over two threads; null for one */
    void split(SplitWork split) {
        this.split = split;
    }

    /**
     * Move every robot through ticks {@code start .. start + n - 1}; the caller has begun tick
     * {@code start} for every robot.
     */
    void move(long start, long n) {
        if (robots.size() == 1) {
            alone(robots.get(0), start, n);
            return;
        }
        boolean capsMove = false;
        for (int i = 0; i < robots.size() && !capsMove; i++) {
            capsMove = robots.get(i).mayMoveCaps(n);
        }
        if (!capsMove) {
            crowd.look(n);
        }
        together.clear();
        lone.clear();
        for (int i = 0; i < robots.size(); i++) {
            SimRobot r = robots.get(i);
            if (!capsMove && crowd.unseen(r)) {
                lone.add(r);
            } else {
                // Values of its last scan left for a later read were those of a robot alone: computed now,
                // before others may come within its sensors' reach.
                r.settleScan();
                together.add(r);
            }
        }
        // No robot can reach one on its own during the stretch, nor it them: they move in any order,
        // on two threads for a large swarm, each touching only what is its own (its bucket follows).
        if (split != null && lone.size() >= SplitWork.MIN_ROBOTS) {
            stretchStart = start;
            stretchTicks = n;
            bodies.deferRelinks();
            try {
                split.forEach(lone.size(), this::moveLone);
            } finally {
                bodies.relinkDeferred();
            }
        } else {
            for (int i = 0; i < lone.size(); i++) {
                alone(lone.get(i), start, n);
            }
        }
        if (together.isEmpty()) {
            return;
        }
        if (!capsMove) {
            crowd.move(together, start, n);
            return;
        }
        for (long k = 0; k < n; k++) {
            long t = start + k;
            if (k > 0) {
                for (int i = 0; i < together.size(); i++) {
                    together.get(i).beginTick(t * Ticks.NANOS);
                }
            }
            for (int i = 0; i < together.size(); i++) {
                SimRobot r = together.get(i);
                r.move(1, (t + 1) * Ticks.NANOS, false, null, 0);
            }
        }
    }

    private void moveLone(int k) {
        alone(lone.get(k), stretchStart, stretchTicks);
    }

    /** No robot: a robot on its own can touch none during the stretch. */
    static final int[] NO_ONE = {};

    /**
     * A robot on its own through the stretch: glides as far as it can, steps where it must,
     * beginning each glide or step as a tick of its own. No other robot can touch it meanwhile.
     */
    private static void alone(SimRobot r, long start, long n) {
        r.sightScope(NO_ONE, 0, 0);
        try {
            aloneUnseen(r, start, n);
        } finally {
            r.sightScope(null, 0, 0);
        }
    }

    private static void aloneUnseen(SimRobot r, long start, long n) {
        long t = start;
        long end = start + n;
        while (t < end) {
            if (t > start) {
                r.beginTick(t * Ticks.NANOS);
            }
            long k = end - t;
            long due = r.nextDueNanos();
            if (due != Long.MAX_VALUE) {
                // Something of its own falls due on the way (its tick begins there).
                k = StrictMath.min(k, -Math.floorDiv(-due, Ticks.NANOS) - t);
            }
            k = StrictMath.max(1, StrictMath.min(k, r.glideTicks(k)));
            r.move(k, (t + k) * Ticks.NANOS, k > 1, NO_ONE, 0);
            t += k;
        }
    }
}
