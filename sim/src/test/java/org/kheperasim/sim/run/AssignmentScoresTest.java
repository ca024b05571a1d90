package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;

/**
 * The teaching controllers reach their assignment's full score, as the arena's tasks count it, on 20
 * seeds each within the arena's time limit: MazeExplorer visits every cell of the three mazes (the
 * paper's first assignment), CapGatherer brings every cap of two-rooms into the lit room (the
 * second; without a livelock), LightFollower follows the beacons to the goal (the third).
 */
class AssignmentScoresTest {
    @ParameterizedTest(name = "{1} in {0}")
    @CsvSource({"maze-easy, MazeExplorer", "maze, MazeExplorer", "maze-hard, MazeExplorer", "two-rooms, CapGatherer",
        "beacon-maze, LightFollower"})
    void fullScoreOnTwentySeeds(String arena, String controller) {
        List<String> misses = new ArrayList<>();
        for (long seed = 1; seed <= 20; seed++) {
            // No --seconds: the run lasts the arena's time limit, as 'run' does.
            Arena a = ArenaFormat.loadBundled(arena);
            double limit = a.assignment().timeLimitSeconds();
            RunResult r = Simulation.builder().arena(a).controller(controller).seed(seed).seconds(limit).run();
            Score score = Score.of(a, RunFacts.of(r));
            if (score.percent() < 100) {
                misses.add("seed " + seed + ": " + score.summary());
            }
            assertTrue(!r.first().status().failed(), "seed " + seed + ": " + r.first().failure());
        }
        assertTrue(misses.isEmpty(), controller + " in " + arena + ": " + misses);
        System.out.printf(Locale.ROOT, "%s in %s: score 100 %% on seeds 1..20%n", controller, arena);
    }
}
