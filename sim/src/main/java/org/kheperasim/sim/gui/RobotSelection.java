package org.kheperasim.sim.gui;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * Which robot the sensor panel and the plot show: the first until the user clicks another robot
 * in the arena view.
 */
final class RobotSelection {
    private volatile int index;
    private final List<Runnable> listeners = new CopyOnWriteArrayList<>();

    /** @return the selected robot's index */
    int index() {
        return index;
    }

    /** Select robot {@code i}; the listeners hear of a change. */
    void select(int i) {
        if (i != index) {
            index = i;
            listeners.forEach(Runnable::run);
        }
    }

    /** @param listener told when another robot is selected */
    void onChange(Runnable listener) {
        listeners.add(listener);
    }

    /** @return the selected robot in {@code s} (the first if the selection is out of range), or null */
    RobotView in(Snapshot s) {
        if (s == null || s.robots().isEmpty()) {
            return null;
        }
        int i = index;
        return s.robots().get(i >= 0 && i < s.robots().size() ? i : 0);
    }

    /** @return the robot whose body covers (x, y) in {@code s}, mm, or -1 */
    static int robotAt(Snapshot s, double x, double y) {
        if (s == null) {
            return -1;
        }
        for (RobotView r : s.robots()) {
            if (StrictMath.hypot(r.x() - x, r.y() - y) <= r.type().body().radiusMm()) {
                return r.id();
            }
        }
        return -1;
    }

    /** @return the robot whose start pose covers (x, y) in {@code arena}, mm, or -1 */
    static int startAt(org.kheperasim.sim.arena.Arena arena, double x, double y) {
        for (int i = 0; i < arena.robots().size(); i++) {
            org.kheperasim.sim.arena.Pose p = arena.robots().get(i);
            if (StrictMath.hypot(p.x() - x, p.y() - y) <= arena.robotType(i).body().radiusMm()) {
                return i;
            }
        }
        return -1;
    }
}
