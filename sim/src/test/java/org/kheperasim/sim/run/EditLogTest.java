package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;

/** Issue 14: an edit stamped off the tick grid, before 0 or after the run is refused, never skipped. */
class EditLogTest {

    private static final Arena LAB = ArenaFormat.loadBundled("lab");
    private static final String ARENA = ArenaFormat.write(LAB);

    private static EditLogException refused(String text) {
        return assertThrows(EditLogException.class, () -> EditLog.parse(text, "run.edits"));
    }

    @Test
    void stampsAreWholeTicksInOrderAndNotNegative() {
        EditLogException e = refused(EditLog.HEADER + "\n@ 10000000001\n" + ARENA + "end\n");
        assertEquals(2, e.line());
        assertTrue(e.getMessage().contains("not on the engine's 1 ms tick grid") && e.getMessage().contains("e.g. 10000000000"),
                e.getMessage());
        assertEquals(2, refused(EditLog.HEADER + "\n@ -1000000\n" + ARENA + "end\n").line());
        assertEquals(2, refused(EditLog.HEADER + "\n@ 99999999999999999999\n" + ARENA + "end\n").line());
        assertEquals(2, refused(EditLog.HEADER + "\n@ 1e9\n" + ARENA + "end\n").line());
        int second = 3 + (int) ARENA.lines().count() + 1;
        e = refused(EditLog.HEADER + "\n@ 2000000\n" + ARENA + "end\n@ 1000000\n" + ARENA + "end\n");
        assertEquals(second, e.line());
        assertTrue(e.getMessage().contains("edits must be in time order"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new EditLog().add(1, LAB));
        assertThrows(IllegalArgumentException.class, () -> new EditLog().add(-1_000_000, LAB));
    }

    @Test
    void aBadArenaInsideIsNamedByTheLogsOwnLine() {
        String bad = ARENA.replace("size ", "size x");
        EditLogException e = refused(EditLog.HEADER + "\n\n@ 0\n" + bad + "end\n");
        assertEquals(3 + 3, e.line(), e.getMessage());
        assertTrue(e.getMessage().startsWith("run.edits:6: in the arena of the edit at line 3: size width is 'x"), e.getMessage());
        assertTrue(refused(EditLog.HEADER + "\n@ 0\n" + ARENA).getMessage().contains("no closing 'end' line"));
        assertEquals(1, refused("khepera-edits 2\n").line());
    }

    @Test
    void everyEditMustFallWithinTheRun() {
        EditLog log = EditLog.parse(EditLog.HEADER + "\n@ 5000000000\n" + ARENA + "end\n@ 70000000000\n" + ARENA + "end\n",
                "run.edits");
        log.checkWithin(70_000_000_000L);
        EditLogException e = assertThrows(EditLogException.class, () -> log.checkWithin(60_000_000_000L));
        assertTrue(e.getMessage().startsWith("run.edits:" + (3 + ARENA.lines().count() + 1) + ": the edit at 70.000 s"),
                e.getMessage());
        IllegalArgumentException run = assertThrows(IllegalArgumentException.class, () -> Simulation.builder().arena(LAB)
                .controller("Braitenberg").seconds(60).edits(log).run());
        assertTrue(run.getMessage().contains("comes after the end of the run at 60.000 s"), run.getMessage());
    }
}
