package org.kheperasim.sim.arena;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** The {@code task} and {@code time-limit} lines: read, written back, refused with file:line and the fix. */
class TaskLinesTest {
    private static final String HEAD = "khepera-arena 1\nsize 1000 1000\nrobot 500 500 0\ncap 100 100\ncap 200 100\n"
            + "region room_a 0 0 400 400\nregion room_b 600 600 1000 1000\nregion goal 900 0 1000 100\n";

    @Test
    void readsEveryKindAndWritesItBack() {
        Arena a = ArenaFormat.parse(HEAD + "time-limit 300\ntask visit room_* goal points 40\ntask cover 25\n"
                + "task deliver caps into room_b points 20\ntask deliver 1 caps into goal\ntask reach goal points 0\n", "t.arena");
        Assignment as = a.assignment();
        assertEquals(300, as.timeLimitSeconds());
        assertEquals(List.of(new Task.Visit(List.of("room_*", "goal"), 40), new Task.Cover(25, 100),
                new Task.Deliver(0, "room_b", 20), new Task.Deliver(1, "goal", 100), new Task.Reach("goal", 0)), as.tasks());
        assertEquals(260, as.maxPoints());
        String text = ArenaFormat.write(a);
        assertTrue(text.endsWith("time-limit 300\ntask visit room_* goal points 40\ntask cover 25\n"
                + "task deliver caps into room_b points 20\ntask deliver 1 caps into goal\ntask reach goal points 0\n"), text);
        assertEquals(a, ArenaFormat.parse(text, "again.arena"));
        assertEquals(List.of("room_a", "room_b"),
                ((Task.Visit) as.tasks().get(0)).regions(a).stream().map(Region::name).toList().subList(0, 2));
    }

    @Test
    void theHashIgnoresTheAssignment() {
        Arena plain = ArenaFormat.parse(HEAD, "a.arena");
        Arena tasked = ArenaFormat.parse(HEAD + "time-limit 10\ntask reach goal\n", "a.arena");
        assertEquals(ArenaFormat.sha256(plain), ArenaFormat.sha256(tasked));
        assertEquals(Assignment.NONE, plain.assignment());
    }

    @ParameterizedTest
    @ValueSource(strings = {"lab", "maze", "two-rooms"})
    void everyBundledArenaHasAnAssignment(String name) {
        Arena a = ArenaFormat.loadBundled(name);
        assertTrue(a.assignment().hasTasks(), name);
        assertTrue(a.assignment().timeLimitSeconds() > 0, name);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "task|9|task needs a kind (visit, cover, deliver, reach)",
        "task fly goal|9|unknown task 'fly'; the tasks are visit, cover, deliver, reach",
        "task visit|9|task visit needs region names or prefixes ending in '*'",
        "task visit nowhere|9|task visit: no region is named 'nowhere'; the regions are room_a, room_b, goal",
        "task visit x*|9|task visit: no region starts with 'x'",
        "task cover|9|task cover needs the percent of the floor to cover",
        "task cover 120|9|task cover percent is 120; give the share of the floor to cover",
        "task cover lots|9|task cover percent is 'lots', not a number",
        "task deliver caps to goal|9|task deliver needs 'caps into <region>'",
        "task deliver 3 caps into goal|9|task deliver asks for 3 caps but the arena has 2; ask for at most 2",
        "task deliver 1.5 caps into goal|9|task deliver count is 1.5; give a whole number",
        "task deliver caps into attic|9|task deliver: no region is named 'attic'",
        "task reach|9|task reach needs one region's name",
        "task reach goal points -1|9|task points are -1; give 0 to",
        "task reach goal points|9|'points <n>' must end a task line",
        "time-limit|9|time-limit needs the simulated seconds a run gets",
        "time-limit 0|9|time-limit is 0 s; give a positive number",
        "time-limit 100000|9|time-limit is 100000 s; give simulated seconds, more than 0 and at most 86400",
    })
    void badLinesNameTheLineAndTheFix(String line, int lineNo, String message) {
        ArenaFormatException e = assertThrows(ArenaFormatException.class, () -> ArenaFormat.parse(HEAD + line + "\n", "t.arena"));
        assertTrue(e.getMessage().startsWith("t.arena:" + lineNo + ": "), e.getMessage());
        assertTrue(e.getMessage().contains(message), e.getMessage());
    }

    @Test
    void aSecondTimeLimitIsRefused() {
        ArenaFormatException e = assertThrows(ArenaFormatException.class,
                () -> ArenaFormat.parse(HEAD + "time-limit 5\ntime-limit 6\n", "t.arena"));
        assertEquals("t.arena:10: a second 'time-limit' line (the first is on line 9); keep one", e.getMessage());
    }

    @Test
    void deliverNeedsCaps() {
        ArenaFormatException e = assertThrows(ArenaFormatException.class, () -> ArenaFormat.parse(
                "khepera-arena 1\nsize 100 100\nrobot 50 50 0\nregion r 0 0 10 10\ntask deliver caps into r\n", "t.arena"));
        assertEquals("t.arena:5: task deliver: the arena has no caps; add 'cap <x> <y>' lines or remove the task", e.getMessage());
    }
}
