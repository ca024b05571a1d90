package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.host.HostOptions;

/**
 * A large swarm's step uses two threads (each robot's scan at a stop, and the moves of robots no
 * other can reach, split between the turn holder and a second thread) and gives the same trace as
 * one thread, byte for byte: a 1,000-robot swarm of step controllers on board, a dense crowd that
 * clusters and pushes caps, and thread-style controllers through the serial link.
 */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SwarmThreadsTest {
    private static final String SECOND_THREAD = "khepera-sim world step, second thread";

    /** {@code n} robots on a lattice of {@code spacing} mm in a walled square, each turned its own way; caps between. */
    static Arena lattice(int n, double spacing, int caps) {
        int side = (int) StrictMath.ceil(StrictMath.sqrt(n));
        double size = side * spacing + 16;
        StringBuilder text = new StringBuilder(String.format(Locale.ROOT,
                "khepera-arena 1\nname lattice\nsize %.1f %.1f\nwall 0 4 %.1f 4 8\nwall 0 %.1f %.1f %.1f 8\n"
                        + "wall 4 0 4 %.1f 8\nwall %.1f 0 %.1f %.1f 8\n",
                size, size, size, size - 4, size, size - 4, size, size - 4, size - 4, size));
        for (int i = 0; i < n; i++) {
            text.append(String.format(Locale.ROOT, "robot %.1f %.1f %d%n", 8 + (i % side + 0.5) * spacing,
                    8 + (i / side + 0.5) * spacing, (i * 137) % 360 - 180));
        }
        for (int k = 0; k < caps; k++) {
            // Between four robots of the lattice.
            int i = (k * 7919) % (n - side - 1);
            text.append(String.format(Locale.ROOT, "cap %.1f %.1f%n", 8 + (i % side + 1) * spacing, 8 + (i / side + 1) * spacing));
        }
        return ArenaFormat.parse(text.toString(), "lattice");
    }

    private record Outcome(String trace, RunResult result, long secondThreadCpuNanos) {
    }

    private static Outcome run(Arena arena, String controller, double seconds, int threads) {
        StringWriter trace = new StringWriter();
        long[] cpu = {-1};
        RunResult result = Simulation.builder().arena(arena).controller(controller).seed(11).seconds(seconds)
                .hostOptions(HostOptions.defaults().withEngineThreads(threads)).trace(trace)
                .listener(s -> cpu[0] = secondThreadCpu(), 1000).run();
        return new Outcome(trace.toString(), result, cpu[0]);
    }

    /** @return the CPU time of the engine's second thread so far, ns; -1 when there is none */
    private static long secondThreadCpu() {
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.getName().equals(SECOND_THREAD) && t.isAlive()) {
                return ManagementFactory.getThreadMXBean().getThreadCpuTime(t.getId());
            }
        }
        return -1;
    }

    private static void assertSameRun(Arena arena, String controller, double seconds) {
        Outcome one = run(arena, controller, seconds, 1);
        Outcome two = run(arena, controller, seconds, 2);
        assertEquals(-1, one.secondThreadCpuNanos(), "one thread: the engine starts no second one");
        assertTrue(two.secondThreadCpuNanos() > 0, "two threads: the second did some of the work");
        assertEquals(one.result().traceSha256(), two.result().traceSha256(), "the same trace, byte for byte");
        assertEquals(one.trace(), two.trace());
        List<String> ends = new ArrayList<>();
        for (RunResult.RobotResult r : two.result().robots()) {
            ends.add(r.status().name());
        }
        assertTrue(ends.stream().noneMatch(s -> s.equals("FAILED") || s.equals("HUNG")), ends.toString());
    }

    @Test
    void aThousandStepControllersOnBoard() {
        assertSameRun(lattice(1000, 200, 0), "StepBraitenberg", 4);
    }

    @Test
    void aDenseCrowdThatClustersAndPushesCaps() {
        // 70 mm apart: robots touch, see each other and push the caps between them.
        assertSameRun(lattice(144, 70, 30), "Aggregation", 15);
    }

    @Test
    void threadStyleControllersThroughTheLink() {
        assertSameRun(lattice(100, 150, 0), "Braitenberg", 5);
    }

    @Test
    void whenTheScansAreNotAllAtOnce() {
        // Tethered step controllers poll at their own pace: the stops have few robots' scans each.
        Arena arena = lattice(400, 120, 0);
        StringWriter one = new StringWriter();
        StringWriter two = new StringWriter();
        for (int threads : new int[] {1, 2}) {
            Simulation.builder().arena(arena).controller("StepBraitenberg").seed(3).seconds(3)
                    .settings(org.kheperasim.sim.engine.model.Settings.defaults().with("controller.mode", "tethered"))
                    .hostOptions(HostOptions.defaults().withEngineThreads(threads)).trace(threads == 1 ? one : two).run();
        }
        assertEquals(one.toString(), two.toString());
    }
}
