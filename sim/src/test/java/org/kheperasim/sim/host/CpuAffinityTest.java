package org.kheperasim.sim.host;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;

/**
 * A run's controller threads keep to one core of their own (Linux), as the operating system's own
 * record of each thread's allowed cores shows, and are let free when the run ends. Under CI
 * (Linux, two cores) pinning must be available, not skipped.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class CpuAffinityTest {
    private static final Arena THREE = org.kheperasim.testfixtures.Arenas.THREE;

    private static boolean ci() {
        return "true".equals(System.getenv("CI"));
    }

    @BeforeEach
    void pinningIsHereOrTheMachineCannot() {
        if (ci()) {
            assertNull(CpuAffinity.unavailable(), "CI runs on Linux with two cores or more: threads can be pinned");
        }
        assumeTrue(CpuAffinity.unavailable() == null, () -> "no pinning here: " + CpuAffinity.unavailable());
    }

    private static String allowedCores() {
        return CpuAffinity.allowedList(Path.of("/proc/thread-self/status"));
    }

    /** A core for the test, or (when another process holds every core, as a window left open may) a skip. */
    private static int claimOrSkip() {
        int core = CpuAffinity.claim();
        if (ci()) {
            assertTrue(core >= 0, "nothing else holds a core under CI");
        }
        assumeTrue(core >= 0, "every core is held by another run");
        return core;
    }

    @Test
    void aPinnedThreadMayRunOnItsCoreOnly() throws Exception {
        AtomicReference<String> seen = new AtomicReference<>();
        int core = claimOrSkip();
        try {
            Thread t = new Thread(() -> {
                seen.set(CpuAffinity.pinCallingThread(core) ? allowedCores() : "not pinned");
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
    void aCoreIsHeldByOneRunAtATimeAndFreeAgainAfterIt() {
        List<Integer> held = new ArrayList<>();
        try {
            for (int c = CpuAffinity.claim(); c >= 0; c = CpuAffinity.claim()) {
                assertFalse(held.contains(c), "claimed twice: " + c + " in " + held);
                held.add(c);
            }
            assumeTrue(!held.isEmpty(), "every core is held by another run");
            int first = held.remove(0);
            CpuAffinity.release(first);
            assertEquals(first, CpuAffinity.claim(), "given back, it can be claimed again");
            held.add(first);
        } finally {
            held.forEach(CpuAffinity::release);
        }
    }

    /** Holds a core in a process of its own until its standard input closes (the test below). */
    public static void main(String[] args) throws Exception {
        int core = CpuAffinity.claim();
        System.out.println("core " + core);
        System.out.flush();
        while (System.in.read() >= 0) {
            // wait
        }
        CpuAffinity.release(core);
    }

    @Test
    void aCoreAnotherProcessHoldsIsNotClaimed() throws Exception {
        Process other = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "--enable-native-access=ALL-UNNAMED", "-cp", System.getProperty("java.class.path"),
                CpuAffinityTest.class.getName()).redirectErrorStream(true).start();
        List<Integer> held = new ArrayList<>();
        try {
            String line;
            BufferedReader out = new BufferedReader(new InputStreamReader(other.getInputStream(), StandardCharsets.UTF_8));
            do {
                line = out.readLine();
            } while (line != null && !line.startsWith("core "));
            assertTrue(line != null, "the other process reported its core");
            int theirs = Integer.parseInt(line.substring(5));
            assumeTrue(theirs >= 0, "every core is held by another run");
            for (int c = CpuAffinity.claim(); c >= 0; c = CpuAffinity.claim()) {
                held.add(c);
            }
            assertFalse(held.contains(theirs), "claimed " + held + " beside the other process's " + theirs);
        } finally {
            held.forEach(CpuAffinity::release);
            other.getOutputStream().close();
            assertTrue(other.waitFor(30, TimeUnit.SECONDS));
        }
    }

    @Test
    void theControllerThreadsOfARunShareOneCoreAndAreFreeAfterIt() throws Exception {
        assumeTrue(!ThreadRunners.VIRTUAL, "virtual controller threads are not pinned: they switch on their carriers");
        List<ConsoleLine> console = new CopyOnWriteArrayList<>();
        RunResult r = Simulation.builder().arena(THREE).controller("org.kheperasim.testcontrollers.CoreReporter")
                .trusted(true).seed(3).seconds(2).console(console::add).run();
        assertEquals(3, r.robots().size());
        List<String> cores = console.stream().map(ConsoleLine::format).filter(l -> l.contains("cores ") || l.contains("failed "))
                .map(l -> l.substring(l.indexOf("cores ") >= 0 ? l.indexOf("cores ") : 0)).toList();
        assertEquals(3, cores.size(), "each robot reported: " + console);
        if (!ci()) {
            assumeTrue(!cores.get(0).contains("-") && !cores.get(0).contains(","), "every core is held by another run");
        }
        assertTrue(cores.get(0).matches("cores \\d+"), "one core: " + cores);
        assertEquals(List.of(cores.get(0), cores.get(0), cores.get(0)), cores, "all on the same core");
        // After the run: the threads the controllers created from their pinned threads (alive for
        // 90 s) are free again, and no thread of this process is kept on that core alone.
        String core = cores.get(0).substring("cores ".length());
        Set<String> children = new HashSet<>();
        try (Stream<Path> tasks = Files.list(Path.of("/proc/self/task"))) {
            for (Path task : tasks.toList()) {
                String allowed = CpuAffinity.allowedList(task.resolve("status"));
                String name = Files.readString(task.resolve("comm")).trim();
                assertNotEquals(core, allowed, "thread '" + name + "' still kept on core " + core);
                if (name.equals("pinned-child")) {
                    children.add(task.getFileName().toString());
                }
            }
        }
        assertEquals(3, children.size(), "the three threads the controllers created are alive");
    }

    @Test
    void aControllerTakenOffAsHungIsLetFreeWhileTheRunGoesOn() throws Exception {
        assumeTrue(!ThreadRunners.VIRTUAL, "virtual controller threads are not pinned: they switch on their carriers");
        System.clearProperty("kheperasim.test.hungTid");
        System.clearProperty("kheperasim.test.hungPort");
        List<ConsoleLine> console = new CopyOnWriteArrayList<>();
        try {
            // Robot 0 gets stuck in a library call once pinned; the two others watch its thread.
            RunResult r = Simulation.builder().arena(THREE).controller("org.kheperasim.testcontrollers.HungWatcher")
                    .robot(0, "org.kheperasim.testcontrollers.HungAfterPinning", null).trusted(true).seed(3).seconds(60)
                    .hostOptions(HostOptions.defaults().withHangTimeout(TimeUnit.SECONDS.toNanos(1)))
                    .console(console::add).run();
            assertEquals(ControllerStatus.HUNG, r.robots().get(0).status(), "robot 0 is hung: " + console);
        } finally {
            org.kheperasim.testcontrollers.HungWatcher.letOut();
        }
        List<String> lines = console.stream().map(ConsoleLine::format).toList();
        String pinned = lines.stream().filter(l -> l.contains("pinned ")).map(l -> l.substring(l.indexOf("pinned ") + 7))
                .findFirst().orElseThrow(() -> new AssertionError("robot 0 reported its cores: " + lines));
        if (!ci()) {
            assumeTrue(pinned.matches("\\d+"), "every core is held by another run");
        }
        assertTrue(pinned.matches("\\d+"), "robot 0 was kept on one core before it hung: " + pinned);
        // The watchers run on after the hung controller is taken off: it must be free by then, not
        // only when the run ends.
        List<String> reports = lines.stream().filter(l -> l.contains("HungWatcher#") && !l.contains(" ERROR ")).toList();
        assertEquals(2, reports.size(), "both watchers reported: " + lines);
        assertTrue(reports.get(0).contains(": freed "), "the hung controller's thread stayed on core " + pinned + ": " + lines);
    }
}
