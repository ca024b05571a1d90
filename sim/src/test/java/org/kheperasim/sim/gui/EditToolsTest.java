package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.Wall;
import org.kheperasim.sim.edit.ArenaEdits;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.edit.Item;
import org.kheperasim.sim.engine.view.Contact;
import org.kheperasim.sim.engine.view.GripperView;
import org.kheperasim.sim.engine.view.RobotView;

/** The editing tools against the model: gestures in millimetres in, arenas out, undo/redo, refusals. */
class EditToolsTest {
    private final EditorModel model = new EditorModel(ArenaFormat.loadBundled("lab"));
    private final EditGestures gestures = new EditGestures(model);
    private final List<String> refusals = new ArrayList<>();

    EditToolsTest() {
        model.onRefusal(refusals::add);
    }

    private void drag(double x1, double y1, double x2, double y2) {
        gestures.press(x1, y1, false, 3);
        gestures.drag((x1 + x2) / 2, (y1 + y2) / 2);
        gestures.drag(x2, y2);
        gestures.release(x2, y2);
    }

    @Test
    void theWallToolDrawsASnappedWallAndUndoRedoTakeItBackAndForth() {
        Arena before = model.arena();
        gestures.setTool(Tool.WALL);
        drag(502, 761, 718, 759);
        assertEquals(before.walls().size() + 1, model.arena().walls().size());
        assertEquals(new Wall(500, 760, 720, 760, ArenaEdits.WALL_THICKNESS), model.arena().walls().get(4));
        assertTrue(model.undo());
        assertEquals(before, model.arena());
        assertTrue(model.redo());
        assertEquals(5, model.arena().walls().size());
        assertFalse(model.redo(), "nothing more to redo");
        assertTrue(model.dirty());
    }

    @Test
    void wallEndsSnapToOtherWallEnds() {
        gestures.setTool(Tool.WALL);
        drag(300, 300, 500, 300);
        drag(507, 304, 500, 500);
        assertEquals(new Wall(500, 300, 500, 500, ArenaEdits.WALL_THICKNESS), model.arena().walls().get(5));
    }

    @Test
    void aWallThroughTheRobotStartIsRefusedVisiblyAndChangesNothing() {
        Arena before = model.arena();
        gestures.setTool(Tool.WALL);
        drag(500, 610, 720, 610);
        assertEquals(before, model.arena(), "refused: the arena is unchanged");
        assertEquals(1, refusals.size());
        assertTrue(refusals.get(0).contains("robot"), refusals.get(0));
        assertNotNull(gestures.refusedAt(), "the view marks where");
        assertFalse(model.canUndo(), "a refused edit leaves nothing to undo");
    }

    @Test
    void selectMoveAndDeleteWithBandSelection() {
        gestures.setTool(Tool.LIGHT);
        gestures.press(301, 299, false, 3);
        gestures.release(301, 299);
        gestures.setTool(Tool.CAP);
        gestures.press(900, 900, false, 3);
        gestures.release(900, 900);
        assertEquals(1, model.arena().lights().size());
        assertEquals(300, model.arena().lights().get(0).x());
        assertEquals(1, model.arena().caps().size());
        gestures.setTool(Tool.SELECT);
        drag(300, 300, 350, 320);
        assertEquals(350, model.arena().lights().get(0).x(), "moved by the snapped drag");
        assertEquals(320, model.arena().lights().get(0).y());
        // Band-select both (the border walls lie outside the band), then delete.
        drag(200, 200, 1000, 1000);
        assertEquals(Set.of(new Item(Item.Kind.LIGHT, 0), new Item(Item.Kind.CAP, 0), new Item(Item.Kind.ROBOT, 0)), model.selection());
        assertTrue(model.deleteSelection());
        assertEquals(0, model.arena().lights().size());
        assertEquals(0, model.arena().caps().size());
        assertEquals(1, model.arena().robots().size(), "a robot's start is never deleted");
        assertTrue(model.undo());
        assertEquals(1, model.arena().lights().size());
    }

    @Test
    void resizeRotateAndRobotAim() {
        gestures.setTool(Tool.WALL);
        drag(300, 300, 500, 300);
        gestures.setTool(Tool.SELECT);
        gestures.press(400, 300, false, 3);
        gestures.release(400, 300);
        drag(500, 300, 500, 400);
        assertEquals(new Wall(300, 300, 500, 400, ArenaEdits.WALL_THICKNESS), model.arena().walls().get(4), "dragging an end resizes");
        model.select(List.of(new Item(Item.Kind.WALL, 4)));
        assertTrue(model.rotateSelection(90));
        Wall w = model.arena().walls().get(4);
        assertEquals(450, w.x1(), 1e-9);
        assertEquals(250, w.y1(), 1e-9);
        gestures.setTool(Tool.ROBOT);
        drag(300, 900, 300, 700);
        assertEquals(new Pose(300, 900, 270), model.arena().robots().get(0), "placed, and aimed down the drag");
        // A start pose inside a wall is refused.
        drag(4, 600, 100, 600);
        assertEquals(new Pose(300, 900, 270), model.arena().robots().get(0));
        assertEquals(1, refusals.size());
    }

    @Test
    void duringARunAWallOnTheRunningRobotAndNewCapsAreRefused() {
        Arena running = model.arena();
        RobotView robot = new RobotView(0, "r", 300, 300, 0, 0, 0, 0, 0, Contact.NONE, new int[8], new int[8], 0, 0, "running",
                new GripperView(180, false, GripperState.OPEN, false, 0, -1), 0);
        model.setRun(() -> running, () -> List.of(robot));
        gestures.setTool(Tool.WALL);
        drag(250, 310, 350, 310);
        assertEquals(running, model.arena());
        assertTrue(refusals.get(0).contains("running robot"), refusals.get(0));
        drag(250, 400, 350, 400);
        assertEquals(5, model.arena().walls().size(), "a wall clear of the robot is fine during a run");
        gestures.setTool(Tool.CAP);
        gestures.press(800, 800, false, 3);
        gestures.release(800, 800);
        assertEquals(0, model.arena().caps().size());
        assertTrue(refusals.get(1).contains("caps"), refusals.get(1));
    }

    @Test
    void editsAreForwardedToTheRunIncludingUndo() {
        List<Arena> forwarded = new ArrayList<>();
        model.onEdit(forwarded::add);
        gestures.setTool(Tool.WALL);
        drag(300, 300, 500, 300);
        model.undo();
        assertEquals(2, forwarded.size());
        assertEquals(4, forwarded.get(1).walls().size());
    }
}
