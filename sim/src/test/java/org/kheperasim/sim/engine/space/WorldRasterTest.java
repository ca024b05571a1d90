package org.kheperasim.sim.engine.space;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.engine.Engine;

/**
 * Runs of one arena share its rasterised grid and distance field (an evaluation runs it thousands
 * of times), each run copying them only when it changes them: an edit in one run, or a cap it
 * moves, never reaches another run.
 */
class WorldRasterTest {
    private static final String ARENA = "khepera-arena 1\nname r\nsize 1219.2 1219.2\nrobot 300 300 0\n"
            + "wall 600 100 600 1100 8\ncap 900 600\n";

    @Test
    void anEditOrAMovedCapInOneRunNeverReachesAnother() {
        Arena arena = ArenaFormat.parse(ARENA, "r.arena");
        World a = new World(arena);
        World b = new World(arena);
        double before = b.field().clearance(560, 600);
        int wallCell = b.grid().id(b.grid().col(600), b.grid().row(600));
        assertEquals(OccupancyGrid.WALL, wallCell);
        // Run a's arena is edited: the wall goes.
        Arena edited = ArenaFormat.parse(ARENA.replace("wall 600 100 600 1100 8\n", ""), "r.arena");
        new Engine(a, 1).edit(edited);
        assertEquals(OccupancyGrid.FLOOR, a.grid().id(a.grid().col(600), a.grid().row(600)), "a's wall is gone");
        assertNotEquals(before, a.field().clearance(560, 600), 1e-9);
        assertEquals(OccupancyGrid.WALL, b.grid().id(b.grid().col(600), b.grid().row(600)), "b's wall stays");
        assertEquals(before, b.field().clearance(560, 600), 0, "b's field stays");
        // A third run of the arena as it was sees the wall too.
        World c = new World(arena);
        assertEquals(OccupancyGrid.WALL, c.grid().id(c.grid().col(600), c.grid().row(600)));
        assertEquals(before, c.field().clearance(560, 600), 0);
        // A cap erased from one run's grid stays in the others'.
        int capCell = c.grid().id(c.grid().col(900), c.grid().row(600));
        c.grid().eraseCap(0, 900, 600, arena.caps().get(0).radius());
        assertEquals(OccupancyGrid.FLOOR, c.grid().id(c.grid().col(900), c.grid().row(600)));
        assertEquals(capCell, new World(arena).grid().id(c.grid().col(900), c.grid().row(600)));
    }
}
