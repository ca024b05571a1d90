package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * Two robots too far apart to see each other, and caps that the first moves while the second, which
 * stands still, watches: the robots never meet, but what one does to a cap is what the other sees,
 * so the event-driven engine must show the watcher the caps where the reference that steps every
 * millisecond has them at each of its samples. A cap may move further in a tick than the part that
 * moves it: fingers lowered beside it, or a cap pushed into another it overlaps.
 */
class CapBetweenRobotsTest {
    private static final String WALLS = "size 600 600\n"
            + "wall 0 4 600 4 8\nwall 0 596 600 596 8\nwall 4 0 4 600 8\nwall 596 0 596 600 8\n";

    private static List<Snapshot> run(Arena arena, String first, double seconds, String stepping) {
        List<Snapshot> seen = new ArrayList<>();
        Simulation.builder().arena(arena).controller("org.kheperasim.testcontrollers." + first)
                .robot(1, "org.kheperasim.testcontrollers.Still", null).seed(3).seconds(seconds)
                .settings(Settings.defaults().with("engine.stepping", stepping)).listener(seen::add, 50).run();
        return seen;
    }

    /** Runs both ways, checks that the watcher saw something, and that both runs are the same. */
    private static void assertWatchedAlike(Arena arena, String first, double seconds) {
        List<Snapshot> tick = run(arena, first, seconds, "tick");
        List<Snapshot> events = run(arena, first, seconds, "events");
        int strongest = 0;
        for (Snapshot s : tick) {
            int[] p = s.robots().get(1).proximity();
            strongest = StrictMath.max(strongest, StrictMath.max(p[2], p[3]));
        }
        // Noise alone stays below about 30 (and the default model has no spikes).
        assertTrue(strongest > 40, "the watcher's front sensors see a cap: at most " + strongest);
        SameRun.assertSameSnapshots(tick, events);
    }

    @Test
    void theWatcherSeesAPushedCapWhereTheReferenceHasIt() {
        assertWatchedAlike(ArenaFormat.parse("khepera-arena 1\nname pushed\n" + WALLS
                + "robot 200 300 0\nrobot 420 300 180\ncap 250 300 radius 22\n", "pushed"), "Straight", 8);
    }

    /** The second cap overlaps the first: the first push shoves it out by the overlap at once. */
    @ParameterizedTest(name = "watcher at x = {0}")
    @ValueSource(doubles = {340, 356, 364})
    void theWatcherSeesACapShovedOutOfAnOverlap(double watcherX) {
        assertWatchedAlike(ArenaFormat.parse("khepera-arena 1\nname overlap\n" + WALLS + "robot 200 300 0\nrobot "
                + watcherX + " 300 180\ncap 237 300\ncap 239 300\n", "overlap"), "Straight", 3);
    }

    /** The lowered fingers land beside a cap and push it aside by their overlap at once. */
    @ParameterizedTest(name = "watcher at y = {0}")
    @ValueSource(doubles = {404, 416, 418})
    void theWatcherSeesACapPushedByFingersComingDown(double watcherY) {
        assertWatchedAlike(ArenaFormat.parse("khepera-arena 1\nname fingers\n" + WALLS + "robot 200 300 0\nrobot 240 "
                + watcherY + " -90\ncap 240 317\n", "fingers"), "CreepLowering", 3);
    }
}
