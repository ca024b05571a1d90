package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.sim.arena.ArenaFormat;

/**
 * The first assignment, visit every location of a maze: the teaching controller MazeExplorer enters
 * every cell of each of the three bundled mazes within 10 simulated minutes, on 20 seeds each.
 */
class MazeExplorerTest {
    @ParameterizedTest
    @ValueSource(strings = {"maze-easy", "maze", "maze-hard"})
    void visitsEveryCellOnTwentySeeds(String arena) {
        int cells = ArenaFormat.loadBundled(arena).regions().size();
        List<String> misses = new ArrayList<>();
        double slowest = 0;
        for (long seed = 1; seed <= 20; seed++) {
            RunResult r = Simulation.builder().arena(arena).controller("MazeExplorer").seed(seed).seconds(600).run();
            int entered = r.first().regionsEntered().size();
            if (entered < cells) {
                misses.add("seed " + seed + ": " + entered + " of " + cells + " cells");
            } else {
                slowest = StrictMath.max(slowest, r.first().regionsEntered().values().stream().mapToDouble(Double::doubleValue).max().orElse(0));
            }
            assertEquals("stopped", r.first().status().name().toLowerCase(java.util.Locale.ROOT), "seed " + seed + ": " + r.first().failure());
        }
        assertTrue(misses.isEmpty(), arena + ": " + misses);
        System.out.printf(java.util.Locale.ROOT, "%s: every cell of %d on 20 seeds, the last entered at %.0f s at the latest%n",
                arena, cells, slowest);
    }
}
