package org.kheperasim.sim.gui.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;

/**
 * Try in arena, without a screen: the selected robot takes the edited type as an arena edit (undone
 * by the main window's Undo), the run going on is ended first and a new one started after.
 */
class TryInArenaTest {
    @Test
    void theSelectedRobotTakesTheTypeAndTheRunStartsAfresh() {
        Arena lab = ArenaFormat.resolve("lab");
        EditorModel model = new EditorModel(lab);
        List<String> calls = new ArrayList<>();
        RobotEditing editing = new RobotEditing(null, model, () -> 0, () -> calls.add("discard"),
                () -> calls.add("start " + model.arena().robotType(0).name()), new RobotFiles(), RobotFiles.bundled());
        RobotType disc = NewRobot.design("disc8", 40, 70, 6, 8, RobotTypes.KHEPERA1);
        String said = editing.tryInArena(disc, null);
        assertEquals(disc, model.arena().robotType(0));
        assertEquals(List.of("discard", "start disc8"), calls.subList(0, 2), "the old run ends before the arena changes; the new one starts with it");
        assertTrue(said.startsWith("Robot 1 of " + lab.name() + " is now disc8"), said);
        String spec = model.arena().robotKinds().get(0).spec();
        assertTrue(spec.endsWith(".yaml") && new RobotFiles().load(Path.of(spec)).equals(disc),
                "a robot not saved is named by a copy in a temporary file: " + spec);
        assertTrue(model.dirty());
        assertTrue(model.undo());
        assertEquals(RobotTypes.KHEPERA1, model.arena().robotType(0), "Undo takes the old robot back");
        editing.tryInArena(RobotTypes.named("epuck"), null);
        assertEquals("epuck", model.arena().robotKinds().get(0).spec(), "a bundled robot is named by its name");
    }
}
