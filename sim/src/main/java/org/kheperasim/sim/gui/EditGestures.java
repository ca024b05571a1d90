package org.kheperasim.sim.gui;

import org.kheperasim.sim.edit.ArenaEdits;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.edit.Item;
import org.kheperasim.sim.edit.ItemHits;
import java.util.List;
import java.util.Set;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.Wall;

/**
 * Turns mouse gestures, already in arena millimetres, into edits of an {@link EditorModel} with the
 * current {@link Tool}: press, drag, release. While a drag goes on the model shows a preview; the
 * edit is applied (and checked, and possibly refused) on release. No Swing here: tests drive it
 * with numbers.
 */
public final class EditGestures {
    /** Grid step positions snap to, mm. */
    public static final double SNAP_MM = 10;
    /** Distance within which a wall end snaps to another wall's end, mm. */
    public static final double SNAP_ENDS_MM = 12;
    /** Shortest wall the wall tool draws, mm. */
    public static final double MIN_WALL_MM = 5;

    private enum Mode { NONE, MOVE, RESIZE, ROTATE, BAND, WALL, ROBOT }

    private final EditorModel model;
    private Tool tool = Tool.SELECT;
    private Mode mode = Mode.NONE;
    private double pressX;
    private double pressY;
    private ItemHits.Handle handle;
    private double[] band;
    private double[] refusedAt;

    /** @param model the model the gestures edit */
    public EditGestures(EditorModel model) {
        this.model = model;
    }

    /** @return the current tool */
    public Tool tool() {
        return tool;
    }

    /** @param t the tool to use from now on */
    public void setTool(Tool t) {
        tool = t;
        mode = Mode.NONE;
        model.preview(null);
    }

    /** @return the rubber band being dragged, x1 y1 x2 y2 mm, or null */
    public double[] band() {
        return band;
    }

    /** @return where the last refused placement was (x, y, radius mm), or null */
    public double[] refusedAt() {
        return refusedAt;
    }

    /** Forget the refusal mark (the user has moved on). */
    public void clearRefusal() {
        refusedAt = null;
    }

    /**
     * A mouse button went down.
     *
     * @param x mm
     * @param y mm
     * @param shift add to / toggle the selection
     * @param tol how close counts as on an item, mm (a few pixels at the current zoom)
     */
    public void press(double x, double y, boolean shift, double tol) {
        refusedAt = null;
        Arena a = model.arena();
        pressX = x;
        pressY = y;
        switch (tool) {
            case SELECT -> {
                handle = ItemHits.handleAt(a, model.selection(), x, y, tol);
                if (handle != null) {
                    mode = handle.which() == 2 ? Mode.ROTATE : Mode.RESIZE;
                    return;
                }
                Item it = ItemHits.hit(a, x, y, tol);
                if (it == null) {
                    if (!shift) {
                        model.select(List.of());
                    }
                    band = new double[] {x, y, x, y};
                    mode = Mode.BAND;
                } else {
                    if (shift) {
                        model.toggle(it);
                    } else if (!model.selection().contains(it)) {
                        model.select(List.of(it));
                    }
                    mode = Mode.MOVE;
                }
            }
            case WALL -> {
                double[] p = snapEnd(a, x, y);
                pressX = p[0];
                pressY = p[1];
                mode = Mode.WALL;
            }
            case LIGHT -> place(ArenaEdits.addLight(a, snap(x), snap(y)), x, y, 20);
            case CAP -> place(ArenaEdits.addCap(a, snap(x), snap(y)), x, y, 15);
            case ROBOT -> {
                pressX = snap(x);
                pressY = snap(y);
                mode = Mode.ROBOT;
                model.preview(ArenaEdits.setRobot(a, 0, new Pose(pressX, pressY, a.robots().get(0).headingDeg())));
            }
        }
    }

    /** The mouse moved with the button down. @param x mm @param y mm */
    public void drag(double x, double y) {
        model.preview(previewAt(x, y));
    }

    /** The button came up. @param x mm @param y mm */
    public void release(double x, double y) {
        Arena next = previewAt(x, y);
        Mode m = mode;
        mode = Mode.NONE;
        if (m == Mode.BAND) {
            double[] b = band;
            band = null;
            java.util.Set<Item> sel = new java.util.LinkedHashSet<>(model.selection());
            sel.addAll(ArenaEdits.inside(model.arena(), b[0], b[1], x, y));
            model.select(sel);
            return;
        }
        if (next == null) {
            model.preview(null);
            return;
        }
        double radius = m == Mode.WALL || m == Mode.MOVE ? 40 : 30;
        place(next, x, y, radius);
    }

    private void place(Arena next, double x, double y, double radius) {
        if (!model.apply(next)) {
            refusedAt = new double[] {x, y, radius};
        }
    }

    private Arena previewAt(double x, double y) {
        Arena a = model.arena();
        try {
            switch (mode) {
                case MOVE -> {
                    double dx = x - pressX;
                    double dy = y - pressY;
                    if (model.snap()) {
                        dx = snap(dx);
                        dy = snap(dy);
                    }
                    return dx == 0 && dy == 0 ? null : ArenaEdits.move(a, model.selection(), dx, dy);
                }
                case RESIZE -> {
                    double[] p = snapEnd(a, x, y);
                    return ArenaEdits.setWallEnd(a, handle.item().index(), handle.which(), p[0], p[1]);
                }
                case ROTATE -> {
                    Pose p = a.robots().get(handle.item().index());
                    return ArenaEdits.setRobot(a, handle.item().index(),
                            new Pose(p.x(), p.y(), heading(p.x(), p.y(), x, y)));
                }
                case BAND -> {
                    band = new double[] {band[0], band[1], x, y};
                    return null;
                }
                case WALL -> {
                    double[] p = snapEnd(a, x, y);
                    if (StrictMath.hypot(p[0] - pressX, p[1] - pressY) < MIN_WALL_MM) {
                        return null;
                    }
                    return ArenaEdits.addWall(a, pressX, pressY, p[0], p[1]);
                }
                case ROBOT -> {
                    double h = StrictMath.hypot(x - pressX, y - pressY) < 10
                            ? a.robots().get(0).headingDeg() : heading(pressX, pressY, x, y);
                    return ArenaEdits.setRobot(a, 0, new Pose(pressX, pressY, h));
                }
                default -> {
                    return null;
                }
            }
        } catch (IllegalArgumentException e) {
            // e.g. a wall with both ends at one point: nothing to show yet
            return null;
        }
    }

    private double heading(double cx, double cy, double x, double y) {
        double deg = ArenaEdits.normalise(StrictMath.toDegrees(StrictMath.atan2(y - cy, x - cx)));
        return model.snap() ? ArenaEdits.normalise(StrictMath.rint(deg / 15) * 15) : ArenaEdits.round(deg);
    }

    private double snap(double v) {
        return model.snap() ? StrictMath.rint(v / SNAP_MM) * SNAP_MM : ArenaEdits.round(v);
    }

    /** Snap a wall end: to a nearby wall end first, else to the grid. */
    private double[] snapEnd(Arena a, double x, double y) {
        if (model.snap()) {
            Set<Item> sel = model.selection();
            double best = SNAP_ENDS_MM;
            double[] out = null;
            for (int i = 0; i < a.walls().size(); i++) {
                if (mode == Mode.RESIZE && handle != null && handle.item().index() == i
                        && sel.contains(handle.item())) {
                    continue;
                }
                Wall w = a.walls().get(i);
                for (double[] e : new double[][] {{w.x1(), w.y1()}, {w.x2(), w.y2()}}) {
                    double d = StrictMath.hypot(x - e[0], y - e[1]);
                    if (d < best) {
                        best = d;
                        out = e;
                    }
                }
            }
            if (out != null) {
                return out;
            }
        }
        return new double[] {snap(x), snap(y)};
    }
}
