package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * The event-driven engine and the reference that steps every millisecond compute the same run:
 * every bundled arena with every bundled controller (120 or 300 s, see {@link #SECONDS}), compared every
 * 10 ms of simulated time. The
 * sensor readings the controller sees, the wheel speeds its commands set, the encoders, contacts,
 * collisions, the gripper, the caps and the regions are equal; poses agree within 1 µm (the two
 * compose the same arcs in different pieces, so they differ only by rounding).
 */
@Timeout(value = 600, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SteppingEquivalenceTest {
    /**
     * A run's length: 120 s, where by 120 s the run already shows all it shows by 300 s (the kinds of
     * command, a collision, the gripper, caps in each region; measured for seed 42), and 300 s for the
     * two runs where it does not (the wall follower's first collision in beacon-maze, the cap gatherer's
     * later deliveries in two-rooms).
     */
    private static final double SECONDS = 120;
    private static final double LONG_SECONDS = 300;
    private static final java.util.Set<String> LONG = java.util.Set.of("beacon-maze WallFollower", "two-rooms CapGatherer");

    static Stream<Arguments> runs() {
        List<Arguments> out = new ArrayList<>();
        for (String arena : org.kheperasim.sim.arena.ArenaFormat.bundledNames()) {
            for (String controller : ControllerCatalog.bundled()) {
                out.add(Arguments.of(arena, controller));
            }
        }
        return out.stream();
    }

    private record Run(List<Snapshot> snapshots, RunResult result) {
    }

    private static double seconds(String arena, String controller) {
        return LONG.contains(arena + " " + controller) ? LONG_SECONDS : SECONDS;
    }

    private static Run run(String arena, String controller, String stepping) {
        List<Snapshot> seen = new ArrayList<>();
        RunResult r = Simulation.builder().arena(arena).controller(controller).seed(42).seconds(seconds(arena, controller))
                .settings(Settings.defaults().with("engine.stepping", stepping)).listener(seen::add, 10).run();
        return new Run(seen, r);
    }

    @ParameterizedTest(name = "{0} with {1}")
    @MethodSource("runs")
    void eventsAndTicksComputeTheSameRun(String arena, String controller) {
        Run tick = run(arena, controller, "tick");
        Run events = run(arena, controller, "events");
        assertEquals(tick.snapshots.size(), events.snapshots.size(), "snapshots");
        assertTrue(tick.snapshots.size() > seconds(arena, controller) * 90, "a snapshot every 10 ms");
        SameRun.assertSameSnapshots(tick.snapshots, events.snapshots);
        assertEquals(tick.result.first().regionsEntered(), events.result.first().regionsEntered(), "regions entered");
        assertEquals(tick.result.capsInRegions(), events.result.capsInRegions(), "caps in regions");
    }
}
