package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.Settings;
import org.kheperasim.sim.engine.Snapshot;

/**
 * Two robots too far apart to see each other, and a cap between them: the first pushes the cap
 * towards the second, which stands still and watches it come. The robots do not meet, but the cap
 * one moves is what the other sees, so the event-driven engine must show the second robot the cap
 * where the reference that steps every millisecond has it at each of its samples.
 */
class CapBetweenRobotsTest {
    private static final Arena ARENA = ArenaFormat.parse("khepera-arena 1\nname cap-between\nsize 600 600\n"
            + "wall 0 4 600 4 8\nwall 0 596 600 596 8\nwall 4 0 4 600 8\nwall 596 0 596 600 8\n"
            + "robot 200 300 0\nrobot 420 300 180\ncap 250 300 radius 22\n", "cap-between");

    private static List<Snapshot> run(String stepping, long listenMillis) {
        List<Snapshot> seen = new ArrayList<>();
        Simulation.builder().arena(ARENA).controller("org.kheperasim.testcontrollers.Straight")
                .robot(1, "org.kheperasim.testcontrollers.Still", null).seed(3).seconds(8)
                .settings(Settings.defaults().with("engine.stepping", stepping)).listener(seen::add, listenMillis).run();
        return seen;
    }

    @Test
    void theWatcherSeesThePushedCapWhereTheReferenceHasIt() {
        List<Snapshot> tick = run("tick", 50);
        List<Snapshot> events = run("events", 50);
        int watched = 0;
        for (Snapshot s : tick) {
            int[] p = s.robots().get(1).proximity();
            if (p[2] > 100 || p[3] > 100) {
                watched++;
            }
        }
        assertTrue(watched > 5, "the watcher's front sensors see the cap coming: " + watched + " snapshots");
        SameRun.assertSameSnapshots(tick, events);
    }
}
