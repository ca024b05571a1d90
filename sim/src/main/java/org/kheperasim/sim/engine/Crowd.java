package org.kheperasim.sim.engine;

import java.util.Arrays;
import java.util.List;
import org.kheperasim.sim.engine.body.DriveBody;
import org.kheperasim.sim.engine.model.Ticks;
import org.kheperasim.sim.engine.space.Bodies;

/**
 * Moves the robots that may see each other during a stretch, without stepping them all tick by
 * tick. Within a stretch nothing but scans and poll samples falls due (no command, noise redraw,
 * controller or snapshot), so a robot's path depends only on the walls and on what it may touch;
 * the other robots matter to it only through its scans, which must see them where they are at the
 * scan's tick (a poll sample reads the robot's own scan and counters, and is taken on the way).
 *
 * <p>So each robot, or each group of robots that may touch each other during the stretch, moves on
 * its own, gliding as far as the walls allow, from one scan to the next. The scans are taken in the
 * order of their ticks (and of the robots within a tick); before a scan, the robots that may come
 * within its sight are moved to its tick too. A scan therefore sees every robot where the
 * tick-by-tick reference has it, and each robot's path is the one it would drive there. While any robot may touch a
 * cap, or its gripper moves or holds one, {@link Motion} keeps
 * these robots to the tick-by-tick lockstep instead: a cap pushed moves while others may be looking
 * at it.
 */
final class Crowd implements Bodies.Visitor {
    /** Two robots' centres farther apart than this neither touch nor report a contact, mm. */
    /** Robot ids are packed below the tick in an event's key. */
    private static final int ID_BITS = 24;

    private final List<SimRobot> robots;
    private final Bodies bodies;
    private final LongHeap events = new LongHeap();
    /** Per robot id: its unit (union-find), the next and the last member of its unit. */
    private int[] parent = new int[0];
    private int[] nextMember = new int[0];
    private int[] lastMember = new int[0];
    /** Per unit root: the tick its robots have been moved to. */
    private long[] movedTo = new long[0];
    /** Per robot id: its sight neighbours, {@code sight[first[i] .. first[i + 1])}. */
    private int[] first = new int[0];
    private int[] sight = new int[64];
    private int sightCount;
    /** The members of the unit being moved (robot ids). */
    private int[] unit = new int[8];
    /**
     * Per unit root: while its robots only turn on the spot (each still, or stalled against another
     * of them), the tick up to which they do so; 0: none known. Such a unit is moved to a tick only
     * by its count; each robot's body is driven there when it is needed (its own scan, the unit's end).
     */
    private long[] frozenUntil = new long[0];
    /** Per robot id: the tick its body has been driven to, while its unit is frozen. */
    private long[] turnedTo = new long[0];
    /** The members of a frozen unit whose robot is driven on its own (robot ids). */
    private int[] mates = new int[8];
    /** The end of the stretch being moved, tick. */
    private long end;

    // The robot whose neighbours are being visited.
    private SimRobot looking;
    private double lookingReach;
    private long ticks;

    Crowd(List<SimRobot> robots, Bodies bodies) {
        this.robots = robots;
        this.bodies = bodies;
    }

    /**
     * Move {@code crowd} (in robot order: the robots {@link #look} found not {@link #unseen})
     * through ticks {@code start .. start + n - 1}, the caller having begun tick {@code start} for
     * each. No robot may move a cap meanwhile ({@link SimRobot#mayMoveCaps} is false for every robot):
     * the caps stay where every sample sees them.
     */
    void move(List<SimRobot> crowd, long start, long n) {
        end = start + n;
        events.clear();
        for (int i = 0; i < crowd.size(); i++) {
            SimRobot r = crowd.get(i);
            movedTo[r.id()] = start;
            schedule(r, end);
        }
        while (!events.isEmpty()) {
            long key = events.pop();
            long tick = key >>> ID_BITS;
            SimRobot r = robots.get((int) (key & ((1 << ID_BITS) - 1)));
            advance(find(r.id()), tick);
            // A scan sees the robots that may come within its reach where they are at its tick.
            for (int k = first[r.id()]; k < first[r.id() + 1]; k++) {
                advance(find(sight[k]), tick);
            }
            turnOne(r.id(), tick);
            r.sightScope(sight, first[r.id()], first[r.id() + 1]);
            r.scanAt(tick * Ticks.NANOS);
            r.sightScope(null, 0, 0);
            schedule(r, end);
        }
        for (int i = 0; i < crowd.size(); i++) {
            advance(find(crowd.get(i).id()), end);
        }
        for (int i = 0; i < crowd.size(); i++) {
            turnOne(crowd.get(i).id(), end);
        }
    }

    private void schedule(SimRobot r, long end) {
        long tick = r.nextScanTick();
        if (tick < end) {
            events.push(tick << ID_BITS | r.id());
        }
    }

    /**
     * Before a stretch of {@code n} ticks: find each robot's sight neighbours (the robots that may
     * come within sight of it, or it of them, whatever they do at their present speeds) and join
     * the robots that may touch into units.
     */
    void look(long n) {
        int count = robots.size();
        if (parent.length < count) {
            parent = new int[count];
            nextMember = new int[count];
            lastMember = new int[count];
            movedTo = new long[count];
            first = new int[count + 1];
            frozenUntil = new long[count];
            turnedTo = new long[count];
        }
        double fastest = 0;
        double unseen = 0;
        for (int id = 0; id < count; id++) {
            SimRobot r = robots.get(id);
            fastest = StrictMath.max(fastest, r.travelPerTickMm());
            unseen = StrictMath.max(unseen, r.unseenMm());
            parent[id] = id;
            nextMember[id] = -1;
            lastMember[id] = id;
            frozenUntil[id] = 0;
        }
        ticks = n;
        sightCount = 0;
        for (int id = 0; id < count; id++) {
            SimRobot r = robots.get(id);
            looking = r;
            lookingReach = r.travelPerTickMm() * n;
            first[id] = sightCount;
            bodies.visit(id, r.x(), r.y(), lookingReach + fastest * n + unseen + bodies.maxRadius(), this);
            first[id + 1] = sightCount;
        }
        // Each unit's members in robot order, listed from its root (its lowest id).
        for (int id = 0; id < count; id++) {
            int root = find(id);
            if (root != id) {
                nextMember[lastMember[root]] = id;
                lastMember[root] = id;
            }
        }
    }

    /** @return true when {@link #look} found no robot that may come within sight of {@code r}, nor it of theirs */
    boolean unseen(SimRobot r) {
        return first[r.id()] == first[r.id() + 1];
    }

    @Override
    public void visit(int k, double dx, double dy) {
        SimRobot o = robots.get(k);
        // The same for both robots of a pair (a sum is exact to swap): one must not find the other
        // within sight while the other finds no one and moves on its own.
        double apart = StrictMath.sqrt(dx * dx + dy * dy) - (lookingReach + o.travelPerTickMm() * ticks);
        if (apart - StrictMath.max(looking.unseenMm(), o.unseenMm())
                - StrictMath.max(looking.radiusMm(), o.radiusMm()) < 0) {
            if (sightCount == sight.length) {
                sight = Arrays.copyOf(sight, sightCount * 2);
            }
            sight[sightCount++] = k;
        }
        if (apart < touch(looking, o)) {
            union(looking.id(), k);
        }
    }

    /** @return how near two robots' centres come when their bodies touch, with the contact margin and rounding, mm */
    private static double touch(SimRobot a, SimRobot b) {
        return a.radiusMm() + b.radiusMm() + DriveBody.CONTACT_EPSILON_MM + 1e-6;
    }

    private int find(int id) {
        while (parent[id] != id) {
            parent[id] = parent[parent[id]];
            id = parent[id];
        }
        return id;
    }

    /** Join two units; the lower id stays the root, so a unit's members list from its lowest. */
    private void union(int a, int b) {
        int ra = find(a);
        int rb = find(b);
        if (ra != rb) {
            parent[StrictMath.max(ra, rb)] = StrictMath.min(ra, rb);
        }
    }

    /** Move the unit whose root is {@code root} on to {@code tick}: no sample of its robots falls due before. */
    private void advance(int root, long tick) {
        long t = movedTo[root];
        if (t >= tick) {
            return;
        }
        movedTo[root] = tick;
        if (nextMember[root] < 0) {
            SimRobot r = robots.get(root);
            while (t < tick) {
                long k = StrictMath.max(1, StrictMath.min(tick - t, r.glideTicks(tick - t)));
                r.move(k, (t + k) * Ticks.NANOS, k > 1, Motion.NO_ONE, 0);
                t += k;
            }
            return;
        }
        if (frozenUntil[root] != 0) {
            if (tick <= frozenUntil[root]) {
                return;
            }
            t = frozenUntil[root];
            turnAll(root, t);
        }
        // Robots that may touch each other step together, tick by tick, in robot order; each can touch
        // only the others of its unit.
        unit = members(root, unit);
        int members = memberCount;
        while (t < tick) {
            long k = glideTogether(members, tick - t);
            if (k <= 1 && (k = frozenTicks(members, t)) > 1) {
                // Each only turns on the spot for k ticks: they are driven there when needed.
                frozenUntil[root] = t + k;
                for (int a = 0; a < members; a++) {
                    turnedTo[unit[a]] = t;
                }
                if (tick <= t + k) {
                    return;
                }
                t += k;
                turnAll(root, t);
            } else if (k > 1) {
                // Too far apart to touch for k ticks: each glides along its arc as it would on its own.
                for (int id = root; id >= 0; id = nextMember[id]) {
                    robots.get(id).move(k, (t + k) * Ticks.NANOS, true, unit, members);
                }
                t += k;
            } else {
                for (int id = root; id >= 0; id = nextMember[id]) {
                    robots.get(id).move(1, (t + 1) * Ticks.NANOS, false, unit, members);
                }
                t++;
            }
        }
    }

    /** How many members {@link #members} found. */
    private int memberCount;

    /** @return {@code into} or a larger copy, listing the members of the unit of {@code root} ({@link #memberCount}) */
    private int[] members(int root, int[] into) {
        int count = 0;
        for (int id = root; id >= 0; id = nextMember[id]) {
            if (count == into.length) {
                into = Arrays.copyOf(into, count * 2);
            }
            into[count++] = id;
        }
        memberCount = count;
        return into;
    }

    /**
     * @return for how many ticks from {@code t} every member of {@link #unit} would only turn on the spot (as
     *     none moves, each goes on doing so while its own stall holds), up to the stretch's end; 0 or 1: step
     */
    private long frozenTicks(int members, long t) {
        for (int a = 0; a < members; a++) {
            if (!robots.get(unit[a]).frozen()) {
                return 0;
            }
        }
        long k = end - t;
        for (int a = 0; a < members && k > 1; a++) {
            k = robots.get(unit[a]).stalledTicks(t, k);
        }
        return k;
    }

    /** The frozen unit of {@code root} is over at {@code tick}: drive each member's body there. */
    private void turnAll(int root, long tick) {
        frozenUntil[root] = 0;
        mates = members(root, mates);
        int count = memberCount;
        for (int a = 0; a < count; a++) {
            turn(mates[a], tick, count);
        }
    }

    /** Drive robot {@code id}'s body to {@code tick} if its unit is frozen (its own scan is taken there). */
    private void turnOne(int id, long tick) {
        int root = find(id);
        if (frozenUntil[root] != 0 && turnedTo[id] < tick) {
            mates = members(root, mates);
            turn(id, tick, memberCount);
        }
    }

    /** Drive robot {@code id}'s body to {@code tick}; its unit's members are the first {@code count} of mates. */
    private void turn(int id, long tick, int count) {
        long k = tick - turnedTo[id];
        if (k > 0) {
            robots.get(id).turnStalled(k, tick * Ticks.NANOS, mates, count);
            turnedTo[id] = tick;
        }
    }

    /**
     * @param members how many robots of {@link #unit} count
     * @param wanted ticks up to the next event
     * @return how many ticks every robot of the unit may glide at once: no two of them can come
     *     within touching distance meanwhile (each moves at most its travel per tick), and none meets a
     *     wall, lamp, cap or region on the way ({@link SimRobot#glideTicks}); 1 or less: step a tick
     */
    private long glideTogether(int members, long wanted) {
        long k = wanted;
        for (int a = 0; a < members && k > 1; a++) {
            SimRobot ra = robots.get(unit[a]);
            for (int b = a + 1; b < members && k > 1; b++) {
                SimRobot rb = robots.get(unit[b]);
                double closing = ra.travelPerTickMm() + rb.travelPerTickMm();
                if (closing > 0) {
                    double gap = StrictMath.hypot(ra.x() - rb.x(), ra.y() - rb.y()) - touch(ra, rb) - 1e-6;
                    k = gap <= 0 ? 0 : (long) StrictMath.min(k, StrictMath.floor(gap / closing));
                }
            }
        }
        for (int a = 0; a < members && k > 1; a++) {
            k = StrictMath.min(k, robots.get(unit[a]).glideTicks(k));
        }
        return k;
    }
}
