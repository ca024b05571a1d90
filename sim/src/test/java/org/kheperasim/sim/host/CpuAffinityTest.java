package org.kheperasim.sim.host;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;

/**
 * A run's controller threads keep to one core (Linux): the operating system's own record of each
 * thread's allowed cores says so. Under CI (Linux, two cores) pinning must be available, not skipped.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class CpuAffinityTest {
    private static final Arena THREE = ArenaFormat.parse("""
            khepera-arena 1
            name three
            size 1219.2 1219.2
            wall 0 4 1219.2 4 8
            wall 0 1215.2 1219.2 1215.2 8
            wall 4 0 4 1219.2 8
            wall 1215.2 0 1215.2 1219.2 8
            robot 300 300 0
            robot 900 300 90
            robot 600 900 180
            """, "three.arena");

    @BeforeEach
    void pinningIsHereOrTheMachineCannot() {
        if ("true".equals(System.getenv("CI"))) {
            assertNull(CpuAffinity.unavailable(), "CI runs on Linux with two cores or more: threads can be pinned");
        }
        assumeTrue(CpuAffinity.unavailable() == null, () -> "no pinning here: " + CpuAffinity.unavailable());
    }

    private static String allowedCores() throws Exception {
        for (String line : Files.readAllLines(Path.of("/proc/thread-self/status"))) {
            if (line.startsWith("Cpus_allowed_list:")) {
                return line.substring("Cpus_allowed_list:".length()).trim();
            }
        }
        throw new AssertionError("no Cpus_allowed_list in /proc/thread-self/status");
    }

    @Test
    void aPinnedThreadMayRunOnItsCoreOnly() throws Exception {
        AtomicReference<String> seen = new AtomicReference<>();
        int core = CpuAffinity.claim();
        try {
            Thread t = new Thread(() -> {
                try {
                    assertTrue(CpuAffinity.pinCallingThread(core));
                    seen.set(allowedCores());
                } catch (Exception e) {
                    seen.set(e.toString());
                }
            });
            t.start();
            t.join();
        } finally {
            CpuAffinity.release(core);
        }
        assertEquals(String.valueOf(core), seen.get());
        assertNotEquals(String.valueOf(core), allowedCores(), "only the thread that asked is pinned");
    }

    @Test
    void runsAtTheSameTimeClaimDifferentCores() {
        int a = CpuAffinity.claim();
        int b = CpuAffinity.claim();
        try {
            assertNotEquals(a, b, "two runs at once, two cores");
        } finally {
            CpuAffinity.release(a);
            CpuAffinity.release(b);
        }
    }

    @Test
    void theControllerThreadsOfARunShareOneCore() {
        assumeTrue(!ThreadRunners.VIRTUAL, "virtual controller threads are not pinned: they switch on their carriers");
        List<ConsoleLine> console = new CopyOnWriteArrayList<>();
        RunResult r = Simulation.builder().arena(THREE).controller("org.kheperasim.testcontrollers.CoreReporter")
                .trusted(true).seed(3).seconds(2).console(console::add).run();
        assertEquals(3, r.robots().size());
        List<String> cores = console.stream().map(ConsoleLine::format).filter(l -> l.contains("cores ") || l.contains("failed "))
                .map(l -> l.substring(l.indexOf("cores ") >= 0 ? l.indexOf("cores ") : 0)).toList();
        assertEquals(3, cores.size(), "each robot reported: " + console);
        assertTrue(cores.get(0).matches("cores \\d+"), "one core: " + cores);
        assertEquals(List.of(cores.get(0), cores.get(0), cores.get(0)), cores, "all on the same core");
    }
}
