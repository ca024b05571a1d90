package org.kheperasim.testing;

import java.util.ArrayList;
import java.util.List;
import java.util.function.LongFunction;
import org.kheperasim.sim.testkit.KitArena;
import org.kheperasim.sim.testkit.TestKit;

/**
 * A recorded run's contacts, worked out from its trace's samples, for recordings only: a trace has no
 * events (its format stays as it is, so that golden traces stay byte for byte), so a live run's contacts
 * come from the engine's events instead ({@link LiveRuns}). A stretch of samples that saw the robot
 * touching becomes one {@link Contact}; what was touched is the thing nearest the robot's body at the
 * sample (a trace records only the side): walls (and the arena's edge), lamps, other robots and caps. A
 * bump that begins and ends between two samples is not seen.
 */
final class RecordedContacts {
    /** How near counts as touching: the simulator's own margin (0.5 mm), and the trace's rounding. */
    private static final double TOUCH_MM = 0.501;

    private final TraceSamples samples;
    private final LongFunction<KitArena> arenaAt;

    /**
     * @param samples the run's samples
     * @param arenaAt the arena as it was at a simulated time, ns (a window's run may have been edited)
     */
    RecordedContacts(TraceSamples samples, LongFunction<KitArena> arenaAt) {
        this.samples = samples;
        this.arenaAt = arenaAt;
    }

    /**
     * @param robot the robot's index
     * @return its contacts that the samples saw, in time order
     */
    List<Contact> contacts(int robot) {
        TraceSamples.Series s = samples.robots.get(robot);
        List<Contact> out = new ArrayList<>();
        Contact open = null;
        for (int k = 0; k < s.size; k++) {
            String side = s.contact[k];
            Obstacle what = null;
            if (!side.equals("NONE")) {
                what = nearest(robot, k);
            } else {
                // The simulator flags a cap only when it blocks the robot; one being pushed touches it too.
                side = capTouching(robot, k);
                what = side == null ? null : Obstacle.CAP;
            }
            if (what != null) {
                if (open != null && open.what() == what) {
                    open = new Contact(open.from(), new SimTime(s.nanos[k]), what, open.side(), open.x(),
                            open.y(), false);
                } else {
                    add(out, open);
                    open = new Contact(new SimTime(s.nanos[k]), new SimTime(s.nanos[k]), what, side,
                            s.x[k], s.y[k], false);
                }
                continue;
            }
            add(out, open);
            open = null;
        }
        add(out, open);
        return out;
    }

    private static void add(List<Contact> out, Contact c) {
        if (c != null) {
            out.add(c);
        }
    }

    /**
     * @return the side of the robot a cap on the floor (or in another robot's gripper) touches at sample
     *     {@code k}, or null when none does
     */
    private String capTouching(int robot, int k) {
        TraceSamples.Series s = samples.robots.get(robot);
        KitArena a = arenaAt.apply(s.nanos[k]);
        for (int c = 0; c < samples.caps.size() && c < a.capCount(); c++) {
            TraceSamples.CapState cap = samples.capAt(c, s.nanos[k]);
            double gap = StrictMath.hypot(s.x[k] - cap.x(), s.y[k] - cap.y()) - a.capRadius(c) - a.robotRadius(robot);
            if (cap.heldBy() != robot && gap <= TOUCH_MM) {
                double rel = StrictMath.atan2(cap.y() - s.y[k], cap.x() - s.x[k]) - StrictMath.toRadians(s.heading[k]);
                return TestKit.sideOf(rel);
            }
        }
        return null;
    }

    /** What lies nearest the robot's body at sample {@code k}. */
    private Obstacle nearest(int robot, int k) {
        Nearest n = new Nearest();
        measure(robot, k, n);
        return n.what;
    }

    private static final class Nearest {
        double gap = Double.POSITIVE_INFINITY;
        Obstacle what = Obstacle.WALL;

        void offer(double g, Obstacle o) {
            if (g < gap) {
                gap = g;
                what = o;
            }
        }
    }

    /** The gaps between the robot's body and everything else at sample {@code k}. */
    private void measure(int robot, int k, Nearest n) {
        TraceSamples.Series s = samples.robots.get(robot);
        double x = s.x[k];
        double y = s.y[k];
        long t = s.nanos[k];
        KitArena a = arenaAt.apply(t);
        double R = a.robotRadius(robot);
        n.offer(StrictMath.min(StrictMath.min(x, a.width() - x), StrictMath.min(y, a.height() - y)) - R, Obstacle.WALL);
        for (KitArena.Wall w : a.walls()) {
            n.offer(segmentDistance(x, y, w.x1(), w.y1(), w.x2(), w.y2()) - w.thickness() / 2 - R, Obstacle.WALL);
        }
        for (KitArena.Lamp l : a.lamps()) {
            n.offer(StrictMath.hypot(x - l.x(), y - l.y()) - l.radius() - R, Obstacle.LAMP);
        }
        for (int j = 0; j < samples.robots.size(); j++) {
            TraceSamples.Series o = samples.robots.get(j);
            int i = o.indexAt(t);
            if (j != robot && i >= 0) {
                n.offer(StrictMath.hypot(x - o.x[i], y - o.y[i]) - (R + a.robotRadius(j)), Obstacle.ROBOT);
            }
        }
        for (int c = 0; c < samples.caps.size() && c < a.capCount(); c++) {
            TraceSamples.CapState cap = samples.capAt(c, t);
            if (cap.heldBy() != robot) {
                n.offer(StrictMath.hypot(x - cap.x(), y - cap.y()) - a.capRadius(c) - R, Obstacle.CAP);
            }
        }
    }

    /** @return the distance from (px, py) to the segment from (x1, y1) to (x2, y2), mm */
    static double segmentDistance(double px, double py, double x1, double y1, double x2, double y2) {
        double dx = x2 - x1;
        double dy = y2 - y1;
        double len2 = dx * dx + dy * dy;
        double u = len2 == 0 ? 0 : ((px - x1) * dx + (py - y1) * dy) / len2;
        u = StrictMath.max(0, StrictMath.min(1, u));
        return StrictMath.hypot(px - (x1 + u * dx), py - (y1 + u * dy));
    }
}
