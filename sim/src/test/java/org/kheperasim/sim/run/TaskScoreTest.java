package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;

/** Scores: each kind of task counted as stated, within the time limit; a run reports them; the window's live count agrees. */
class TaskScoreTest {
    private static final Arena ARENA = ArenaFormat.parse("khepera-arena 1\nname t\nsize 1000 1000\nrobot 100 100 90\n"
            + "cap 500 500\ncap 600 600\nregion a1 0 0 200 200\nregion a2 200 0 400 200\nregion a3 400 0 600 200\n"
            + "region goal 800 800 1000 1000\ntask visit a*\ntask deliver goal 2\ntask reach goal\ntime-limit 100\n", "t");

    @Test
    void eachTaskIsCountedWithinTheTimeLimit() {
        List<TaskScore> s = TaskScore.score(ARENA, Map.of("a1", 0.0, "a2", 50.0, "a3", 150.0, "goal", 99.5),
                Map.of("goal", 1, "a1", 0));
        assertEquals(2.0 / 3, s.get(0).fraction(), 1e-12, "a3 was entered after the limit");
        assertEquals("2 of 3 regions entered", s.get(0).detail());
        assertEquals(0.5, s.get(1).fraction());
        assertEquals(1, s.get(2).fraction());
        assertEquals(72, TaskScore.total(s), "(2/3 + 1/2 + 1) / 3 = 72.2 %");
        assertTrue(TaskScore.describe(s).startsWith("score 72 % (task visit a*: 2 of 3 regions entered; "), TaskScore.describe(s));
    }

    @Test
    void aRunReportsItsScoreAndTheLiveCountAgrees() {
        TaskProgress live = new TaskProgress(ArenaFormat.loadBundled("maze"));
        RunResult r = Simulation.builder().arena("maze").controller("MazeExplorer").seed(4).seconds(120)
                .listener(live, 20).run();
        assertEquals(1, r.scores().size());
        int entered = r.regionsEnteredByAny().size();
        assertTrue(entered > 10 && entered < 25, "two minutes: part of the maze, " + entered);
        assertEquals(entered + " of 25 regions entered", r.scores().get(0).detail());
        assertEquals(r.scores(), live.scores(), "the window's count from 20 ms snapshots");
    }
}
