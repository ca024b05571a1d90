package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.host.ControllerHost;
import org.kheperasim.sim.host.ControllerStatus;

/** The engine holds a list of robots: three controllers pass the turn between them deterministically. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class MultiRobotTest {
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

    private static RunResult run(StringWriter trace, ControllerHost.Options options) {
        return Simulation.builder().arena(THREE).controller("Braitenberg").seed(21).seconds(60).trace(trace)
                .sampleMillis(20).hostOptions(options).run();
    }

    @Test
    void everyRobotRunsItsOwnControllerAndTheRunRepeatsExactly() {
        StringWriter a = new StringWriter();
        StringWriter b = new StringWriter();
        RunResult first = run(a, ControllerHost.Options.defaults());
        run(b, ControllerHost.Options.defaults().withJitter(200));
        assertEquals(a.toString(), b.toString(), "three controllers in lockstep give the same trace every time");
        assertEquals(3, first.robots().size());
        for (RunResult.RobotResult r : first.robots()) {
            assertTrue(r.distanceMm() > 1000, r.name() + " drove " + r.distanceMm() + " mm");
            assertEquals(ControllerStatus.STOPPED, r.status());
        }
        assertNotEquals(first.robots().get(0).x(), first.robots().get(1).x());
        assertEquals(3 * (60 * 50 + 1), a.toString().lines().filter(l -> !l.startsWith("#")).count());
    }
}
