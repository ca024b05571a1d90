package org.kheperasim.sim.edit;

import java.util.List;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.Wall;
import org.kheperasim.sim.engine.view.RobotView;

/**
 * Whether an edited arena is possible. The arena file's own checks decide (a robot start inside a
 * wall, something outside the arena: exactly what loading the saved file would refuse); while a
 * run goes on, a wall or lamp must also not land on a running robot, and the arena keeps its size,
 * its robots and its caps (they can be moved, not added or removed).
 */
public final class ArenaCheck {
    private ArenaCheck() {
    }

    /**
     * @param edited the arena after the edit
     * @param before the arena before the edit (only what the edit adds or moves is checked against live robots)
     * @param running the arena of the run going on, or null when no run is going on
     * @param live the running robots (may be empty)
     * @return what is wrong, for the user, or null when the arena is possible
     */
    public static String problem(Arena edited, Arena before, Arena running, List<RobotView> live) {
        try {
            ArenaFormat.parse(ArenaFormat.write(edited), "arena");
        } catch (IllegalArgumentException e) { // ArenaFormatException is one
            String m = e.getMessage();
            return m.replaceFirst("^arena:\\d+: ", "");
        }
        if (running != null) {
            if (edited.width() != running.width() || edited.height() != running.height()) {
                return "the arena's size cannot change while a run goes on; stop the run first";
            }
            if (edited.robots().size() != running.robots().size()) {
                return "robots cannot be added or removed while a run goes on; stop the run first";
            }
            if (edited.caps().size() != running.caps().size()) {
                return "caps can be moved but not added or removed while a run goes on; stop the run first";
            }
        }
        for (RobotView r : live) {
            double clear = r.type().body().radiusMm();
            for (Wall w : edited.walls()) {
                if (!before.walls().contains(w) && segmentDistance(r.x(), r.y(), w) < clear + w.thickness() / 2) {
                    return String.format(java.util.Locale.ROOT,
                            "a wall there would land on the running robot at (%.0f, %.0f) mm; place it at least %.1f mm"
                                    + " from the robot's centre",
                            r.x(), r.y(), clear + w.thickness() / 2);
                }
            }
            for (Light l : edited.lights()) {
                if (!before.lights().contains(l)
                        && StrictMath.hypot(r.x() - l.x(), r.y() - l.y()) < clear + l.radius()) {
                    return String.format(java.util.Locale.ROOT,
                            "a lamp there would land on the running robot at (%.0f, %.0f) mm",
                            r.x(), r.y());
                }
            }
        }
        return null;
    }

    /** @return distance from (px, py) to the wall's centre line, mm */
    public static double segmentDistance(double px, double py, Wall w) {
        double dx = w.x2() - w.x1();
        double dy = w.y2() - w.y1();
        double len2 = dx * dx + dy * dy;
        double t = len2 == 0 ? 0 : ((px - w.x1()) * dx + (py - w.y1()) * dy) / len2;
        t = StrictMath.max(0, StrictMath.min(1, t));
        return StrictMath.hypot(px - (w.x1() + t * dx), py - (w.y1() + t * dy));
    }
}
