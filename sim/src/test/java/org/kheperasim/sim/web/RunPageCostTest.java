package org.kheperasim.sim.web;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.testfixtures.Arenas;

/**
 * What pages cost a grading: grade writes one page per run from the run's trace, in the grading's
 * own JVM. A grading takes about 1 s of wall time per run (a child JVM each); its pages may add at
 * most a tenth. The figures are printed; the bound asserted is ten times looser, for a loaded machine.
 */
@Tag("timing")
@Timeout(value = 600, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RunPageCostTest {
    @TempDir
    Path dir;

    @Test
    void thirtyPagesOfSixHundredSecondRunsAddLittleToAGrading() {
        Arena maze = ArenaFormat.loadBundled("maze");
        Path trace = dir.resolve("maze.trace");
        RunResult result = Simulation.builder().arena(maze).controller("WallFollower").seed(1).seconds(600).trace(trace)
                .console(l -> { }).run();
        RunOutcome outcome = RunOutcome.of(result);
        RunPage.write(trace, maze, outcome, dir.resolve("warm.html"));
        int runs = 30;
        java.lang.management.ThreadMXBean threads = java.lang.management.ManagementFactory.getThreadMXBean();
        long start = System.nanoTime();
        long cpu = threads.getCurrentThreadCpuTime();
        long bytes = 0;
        for (int i = 0; i < runs; i++) {
            bytes += RunPage.write(trace, maze, outcome, dir.resolve("run" + i + ".html")).bytes();
        }
        double each = (System.nanoTime() - start) / 1e9 / runs;
        double cpuEach = (threads.getCurrentThreadCpuTime() - cpu) / 1e9 / runs;
        // CPU time is what a page costs on an idle machine; wall time here also counts whatever else runs.
        System.out.printf("pages for a grading: %d pages of a 600 s run (maze, 1 robot), %.3f s of CPU each (%.3f s of wall"
                + " time on this machine now), %d bytes each; %.0f%% of a grading that takes 1 s a run%n", runs, cpuEach, each,
                bytes / runs, 100 * cpuEach);
        assertTrue(each < 1.0, "a page took " + each + " s to write");
    }

    @Test
    void aPageOfThreeRobotsCostsAFewTimesMore() {
        Path trace = dir.resolve("three.trace");
        Simulation.builder().arena(Arenas.THREE).controller("Braitenberg").seed(1).seconds(600).trace(trace).console(l -> { }).run();
        RunPage.write(trace, Arenas.THREE, RunOutcome.none(), dir.resolve("warm.html"));
        java.lang.management.ThreadMXBean threads = java.lang.management.ManagementFactory.getThreadMXBean();
        long cpu = threads.getCurrentThreadCpuTime();
        int pages = 5;
        RunPage.Written w = null;
        for (int i = 0; i < pages; i++) {
            w = RunPage.write(trace, Arenas.THREE, RunOutcome.none(), dir.resolve("three" + i + ".html"));
        }
        double cpuEach = (threads.getCurrentThreadCpuTime() - cpu) / 1e9 / pages;
        System.out.printf("a page of a 600 s run of 3 robots: %.3f s of CPU, %d bytes, sensor values every %d ms%n", cpuEach,
                w.bytes(), w.sensorsEveryMs());
        assertTrue(cpuEach < 3.0, "a page took " + cpuEach + " s of CPU");
    }
}
