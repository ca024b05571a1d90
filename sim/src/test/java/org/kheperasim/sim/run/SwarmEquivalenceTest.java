package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * Many robots close together, the case where the event-driven engine moves robots that see each
 * other on their own between their sensor samples: it must compute the same run as the reference
 * that steps every millisecond (see {@link SameRun}). Sixteen robots 170 mm apart in a walled
 * square, with and without caps, run by a thread-style and two step-style controllers, one of
 * which gathers them into touching clumps.
 */
@Timeout(value = 600, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SwarmEquivalenceTest {
    private static final double SECONDS = 120;

    static Stream<Arguments> runs() {
        List<Arguments> out = new ArrayList<>();
        for (boolean caps : new boolean[] {false, true}) {
            for (String controller : List.of("Braitenberg", "StepBraitenberg", "Aggregation")) {
                out.add(Arguments.of(caps ? "with caps" : "no caps", controller));
            }
        }
        return out.stream();
    }

    /** Sixteen robots on a 170 mm lattice, each turned its own way; with caps, three among them. */
    static Arena crowd(boolean caps) {
        StringBuilder text = new StringBuilder("khepera-arena 1\nname crowd\nsize 800 800\n"
                + "wall 0 4 800 4 8\nwall 0 796 800 796 8\nwall 4 0 4 800 8\nwall 796 0 796 800 8\n");
        for (int i = 0; i < 16; i++) {
            double x = 145 + (i % 4) * 170 + ((i * 7) % 5 - 2) * 6;
            double y = 145 + (i / 4) * 170 + ((i * 3) % 5 - 2) * 6;
            text.append(String.format(Locale.ROOT, "robot %.1f %.1f %d%n", x, y, (i * 137) % 360 - 180));
        }
        if (caps) {
            text.append("cap 230 230\ncap 400 485\ncap 570 315\n");
        }
        return ArenaFormat.parse(text.toString(), "crowd");
    }

    private static List<Snapshot> run(Arena arena, String controller, String stepping) {
        List<Snapshot> seen = new ArrayList<>();
        Simulation.builder().arena(arena).controller(controller).seed(7).seconds(SECONDS)
                .settings(Settings.defaults().with("engine.stepping", stepping)).listener(seen::add, 10).run();
        return seen;
    }

    @ParameterizedTest(name = "{0}, {1}")
    @MethodSource("runs")
    void eventsAndTicksComputeTheSameSwarmRun(String caps, String controller) {
        Arena arena = crowd(caps.equals("with caps"));
        List<Snapshot> tick = run(arena, controller, "tick");
        List<Snapshot> events = run(arena, controller, "events");
        assertTrue(tick.size() > SECONDS * 90, "a snapshot every 10 ms");
        assertEquals(16, tick.get(0).robots().size(), "robots");
        SameRun.assertSameSnapshots(tick, events);
    }
}
