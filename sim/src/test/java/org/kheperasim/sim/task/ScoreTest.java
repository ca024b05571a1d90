package org.kheperasim.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;

/** Scores as a user reads them: points in proportion to what was done, from a result or a live engine. */
class ScoreTest {
    private static final Arena ARENA = ArenaFormat.parse("khepera-arena 1\nsize 1000 1000\nrobot 500 500 0\n"
            + "cap 100 100\ncap 200 100\nregion a 0 0 400 400\nregion b 600 600 1000 1000\nregion goal 900 0 1000 100\n"
            + "task visit a b points 50\ntask cover 20 points 10\ntask deliver caps into a\ntask reach goal points 40\n", "s.arena");

    @Test
    void eachTaskEarnsItsShare() {
        RunFacts f = new RunFacts(60, Map.of("a", 3.0, "goal", 41.25), 5, Map.of("a", 1, "b", 0, "goal", 0), 2);
        Score s = Score.of(ARENA, f);
        assertEquals(200, s.max());
        assertEquals(25 + 2.5 + 50 + 40, s.points(), 1e-9);
        assertEquals(58.75, s.percent(), 1e-9);
        assertEquals("117.5/200 (visit a b points 50: 1/2 regions; cover 20 points 10: 5.0% of 20% of the floor;"
                + " deliver caps into a: 1/2 caps; reach goal points 40: reached at 41.3 s)", s.summary());
    }

    @Test
    void noTasksNoPoints() {
        Score s = Score.of(ArenaFormat.parse("khepera-arena 1\nsize 100 100\nrobot 50 50 0\n", "n.arena"),
                new RunFacts(1, Map.of(), 0, Map.of(), 0));
        assertEquals(0, s.max());
        assertEquals(0, s.percent());
        assertTrue(s.parts().isEmpty());
    }

    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void capGathererScoresFullMarksInTwoRooms() {
        RunResult r = Simulation.builder().arena("two-rooms").controller("CapGatherer").seed(1).seconds(1200).run();
        Score s = Score.of(ArenaFormat.loadBundled("two-rooms"), RunFacts.of(r));
        assertEquals(100, s.percent(), 1e-9, s.summary());
    }
}
