package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
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
 *
 * <p>A cell once visited and a goal once reached stay so: those runs end at the first full score
 * (checked every 10 simulated seconds: the live score is not free), which then is the score at the time limit too; they reach it
 * after a quarter to a half of the limit. Caps delivered may be carried out again, so two-rooms
 * runs to its limit and is scored there, as {@code run} scores it.
 */
class AssignmentScoresTest {
    @ParameterizedTest(name = "{1} in {0}")
    @CsvSource({"maze-easy, MazeExplorer, true", "maze, MazeExplorer, true", "maze-hard, MazeExplorer, true",
        "two-rooms, CapGatherer, false", "beacon-maze, LightFollower, true"})
    void fullScoreOnTwentySeeds(String arena, String controller, boolean fullStaysFull) {
        List<String> misses = new ArrayList<>();
        Arena a = ArenaFormat.loadBundled(arena);
        double limit = a.assignment().timeLimitSeconds();
        for (long seed = 1; seed <= 20; seed++) {
            // No --seconds: the run lasts the arena's time limit, as 'run' does (or until full score where that stays).
            Simulation.Builder run = Simulation.builder().arena(a).controller(controller).seed(seed).seconds(limit);
            if (fullStaysFull) {
                AtomicReference<RunSession> session = new AtomicReference<>();
                AtomicBoolean full = new AtomicBoolean();
                // The listener runs on the thread that steps the engine, where the live score may be taken.
                run.onStart(session::set).listener(s -> full.compareAndSet(false, Score.live(session.get().engine()).percent() >= 100),
                        10_000).stopWhen(full::get);
            }
            RunResult r = run.run();
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
