package org.kheperasim.sim.engine.event;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.kheperasim.sim.arena.Region;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.Contact;

/**
 * One robot's side of the events: what it touched and which regions it was in at its last move, and
 * the events of the moves since the last stretch ended. Only the thread moving the robot touches it
 * until the stretch ends.
 */
final class RobotWatch {
    private final SimRobot robot;
    private final World world;
    private final Touches touches;
    private Touched touching;
    private double lastX;
    private double lastY;
    private long lastEnd;
    private final Set<Region> inside = new LinkedHashSet<>();
    final List<EngineEvent> pending = new ArrayList<>();

    RobotWatch(SimRobot robot, World world, Touches touches, long now) {
        this.robot = robot;
        this.world = world;
        this.touches = touches;
        this.lastEnd = now;
        moved(now);
    }

    /**
     * The robot's move ended at {@code end}. A move is a single tick with contact handling or a glide
     * along which nothing can be touched: a contact ends at the glide's first tick.
     */
    void moved(long end) {
        double x = robot.x();
        double y = robot.y();
        Contact side = robot.contact();
        Touched now = side == Contact.NONE ? null : touches.of(robot);
        if (now == null && side != Contact.NONE) {
            now = touching;
        }
        if (side == Contact.NONE && world.capCount() > 0) {
            // A cap that gives way is pushed, not flagged: it touches the body all the same.
            int cap = touches.pushedCap(robot);
            if (cap >= 0) {
                now = new Touched(Touched.Kind.CAP, cap);
                side = touches.sideOfCap(robot, cap);
            }
        }
        if (now == null ? touching != null : !now.equals(touching)) {
            if (touching != null) {
                long at = now == null ? StrictMath.min(end, lastEnd + Engine.TICK_NANOS) : end;
                pending.add(new ContactEnded(robot.id(), at, touching, lastX, lastY));
            }
            if (now != null) {
                pending.add(new ContactBegan(robot.id(), end, now, side, x, y));
            }
            touching = now;
        }
        regions(end, x, y);
        if (touching != null) {
            lastX = x;
            lastY = y;
        }
        lastEnd = end;
    }

    private void regions(long end, double x, double y) {
        List<Region> regions = world.arena().regions();
        if (regions.isEmpty() && inside.isEmpty()) {
            return;
        }
        // A region the arena no longer has (an edit) is forgotten without an event.
        inside.retainAll(regions);
        for (var it = inside.iterator(); it.hasNext(); ) {
            Region r = it.next();
            if (!r.contains(x, y)) {
                it.remove();
                pending.add(new RegionLeft(robot.id(), end, r, x, y));
            }
        }
        for (Region r : regions) {
            if (r.contains(x, y) && inside.add(r)) {
                pending.add(new RegionEntered(robot.id(), end, r, x, y));
            }
        }
    }
}
