package org.kheperasim.sim.arena;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Tasks and time limits in arena files: read, written back, and refused with the line and the fix. */
class AssignmentFormatTest {
    private static final String BASE = "khepera-arena 1\nname t\nsize 1000 1000\nrobot 100 100 90\ncap 500 500\ncap 600 600\n"
            + "region a1 0 0 200 200\nregion a2 200 0 400 200\nregion goal 800 800 1000 1000\n";

    @Test
    void tasksAreReadAndWrittenBack() {
        Arena a = ArenaFormat.parse(BASE + "task visit a*\ntask deliver goal 2\ntask reach goal\ntime-limit 300\n", "t.arena");
        Assignment s = a.assignment();
        assertEquals(3, s.tasks().size());
        assertEquals(new Task(Task.Kind.VISIT, List.of("a*"), 0), s.tasks().get(0));
        assertEquals(List.of("a1", "a2"), s.tasks().get(0).matching(a));
        assertEquals(new Task(Task.Kind.DELIVER, List.of("goal"), 2), s.tasks().get(1));
        assertEquals(300, s.timeLimitSeconds());
        String text = ArenaFormat.write(a);
        assertTrue(text.contains("task visit a*\ntask deliver goal 2\ntask reach goal\ntime-limit 300\n"), text);
        assertEquals(a, ArenaFormat.parse(text, "again"));
        assertEquals(Assignment.NONE, ArenaFormat.parse(BASE, "t").assignment());
    }

    @Test
    void everyBundledMazeAsksForEveryCell() {
        for (String maze : List.of("maze-easy", "maze", "maze-hard")) {
            Arena a = ArenaFormat.loadBundled(maze);
            assertEquals(a.regions().size(), a.assignment().tasks().get(0).matching(a).size(), maze);
            assertEquals(600, a.assignment().timeLimitSeconds(), maze);
        }
        assertEquals(Task.Kind.DELIVER, ArenaFormat.loadBundled("two-rooms").assignment().tasks().get(0).kind());
    }

    @Test
    void badTaskLinesNameTheLineAndTheFix() {
        assertError("task visit nowhere\n", ":10: ", "names the region 'nowhere', and the arena has none");
        assertError("task visit b*\n", ":10: ", "regions starting 'b'");
        assertError("task deliver goal 3\n", ":10: ", "asks for 3 caps and the arena has 2");
        assertError("task deliver goal\n", ":10: ", "needs a region and a number of caps");
        assertError("task deliver goal two\n", ":10: ", "not a whole number");
        assertError("task reach a1 a2\n", ":10: ", "names one region, not 2");
        assertError("task fly goal\n", ":10: ", "unknown task 'fly'; tasks are visit, deliver and reach");
        assertError("task\n", ":10: ", "task needs a kind and a region");
        assertError("time-limit 0\n", ":10: ", "out of range");
        assertError("time-limit 10\ntime-limit 20\n", ":11: ", "a second 'time-limit' line (the first is line 10)");
        assertError("time-limit soon\n", ":10: ", "not a number");
        assertError("region b 0 0 1 1\ntask visit a1\ntask visit nope\n", ":12: ", "'nope'");
    }

    private static void assertError(String lines, String at, String what) {
        ArenaFormatException e = assertThrows(ArenaFormatException.class, () -> ArenaFormat.parse(BASE + lines, "t.arena"));
        assertTrue(e.getMessage().startsWith("t.arena" + at), e.getMessage());
        assertTrue(e.getMessage().contains(what), e.getMessage());
    }
}
