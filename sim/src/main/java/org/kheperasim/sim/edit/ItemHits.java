package org.kheperasim.sim.edit;

import java.util.Set;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.Wall;

/**
 * What the pointer is on in the editor: the topmost item at a point, or the handle of a selected
 * item (the shapes the window draws, tested in arena millimetres).
 */
public final class ItemHits {
    /** How far ahead of a robot's centre its heading handle is, mm. */
    public static final double HEADING_HANDLE_MM = 45;

    /**
     * A handle of a selected item.
     *
     * @param item the item
     * @param which 0 or 1: a wall's ends; 2: a robot's heading
     */
    public record Handle(Item item, int which) {
    }

    private ItemHits() {
    }

    /**
     * The topmost item at a point: robots, then caps, lamps, walls (the order they are drawn in,
     * reversed).
     *
     * @param a the arena
     * @param x mm
     * @param y mm
     * @param tol extra tolerance, mm
     * @return the item, or null
     */
    public static Item hit(Arena a, double x, double y, double tol) {
        for (int i = a.robots().size() - 1; i >= 0; i--) {
            Pose p = a.robots().get(i);
            if (StrictMath.hypot(x - p.x(), y - p.y()) <= a.robotType(i).body().radiusMm() + tol) {
                return new Item(Item.Kind.ROBOT, i);
            }
        }
        for (int i = a.caps().size() - 1; i >= 0; i--) {
            Cap c = a.caps().get(i);
            if (StrictMath.hypot(x - c.x(), y - c.y()) <= c.radius() + tol) {
                return new Item(Item.Kind.CAP, i);
            }
        }
        for (int i = a.lights().size() - 1; i >= 0; i--) {
            Light l = a.lights().get(i);
            if (StrictMath.hypot(x - l.x(), y - l.y()) <= l.radius() + tol) {
                return new Item(Item.Kind.LIGHT, i);
            }
        }
        for (int i = a.walls().size() - 1; i >= 0; i--) {
            Wall w = a.walls().get(i);
            if (ArenaCheck.segmentDistance(x, y, w) <= w.thickness() / 2 + tol) {
                return new Item(Item.Kind.WALL, i);
            }
        }
        return null;
    }

    /**
     * The handle of a selected item at a point: a wall's end, a robot's heading.
     *
     * @return the handle, or null
     */
    public static Handle handleAt(Arena a, Set<Item> selection, double x, double y, double tol) {
        for (Item it : selection) {
            if (!EditorModel.exists(a, it)) {
                continue;
            }
            if (it.kind() == Item.Kind.WALL) {
                Wall w = a.walls().get(it.index());
                if (StrictMath.hypot(x - w.x1(), y - w.y1()) <= tol) {
                    return new Handle(it, 0);
                }
                if (StrictMath.hypot(x - w.x2(), y - w.y2()) <= tol) {
                    return new Handle(it, 1);
                }
            } else if (it.kind() == Item.Kind.ROBOT) {
                Pose p = a.robots().get(it.index());
                double hx = p.x() + HEADING_HANDLE_MM * StrictMath.cos(StrictMath.toRadians(p.headingDeg()));
                double hy = p.y() + HEADING_HANDLE_MM * StrictMath.sin(StrictMath.toRadians(p.headingDeg()));
                if (StrictMath.hypot(x - hx, y - hy) <= tol) {
                    return new Handle(it, 2);
                }
            }
        }
        return null;
    }
}
