package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.host.ControllerStatus;
import org.kheperasim.sim.host.HostOptions;

/** The engine holds a list of robots: three controllers pass the turn between them deterministically. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class MultiRobotTest {
    private static final Arena THREE = org.kheperasim.testfixtures.Arenas.THREE;

    private static RunResult run(StringWriter trace, HostOptions options) {
        return Simulation.builder().arena(THREE).controller("Braitenberg").seed(21).seconds(60).trace(trace)
                .sampleMillis(20).hostOptions(options).run();
    }

    @Test
    void everyRobotRunsItsOwnControllerAndTheRunRepeatsExactly() {
        StringWriter a = new StringWriter();
        StringWriter b = new StringWriter();
        RunResult first = run(a, HostOptions.defaults());
        run(b, HostOptions.defaults().withJitter(200));
        assertEquals(a.toString(), b.toString(), "three controllers in lockstep give the same trace every time");
        assertEquals(3, first.robots().size());
        for (RunResult.RobotResult r : first.robots()) {
            assertTrue(r.distanceMm() > 1000, r.name() + " drove " + r.distanceMm() + " mm");
            assertEquals(ControllerStatus.STOPPED, r.status());
        }
        assertNotEquals(first.robots().get(0).x(), first.robots().get(1).x());
        assertEquals(3 * (60 * 50 + 1), a.toString().lines().filter(l -> !l.startsWith("#")).count());
    }

    /**
     * Each robot's controller class is loaded by its own class loader, so each of these three
     * waits inside its own class initializer while the others run: none of them, and not the
     * Braitenberg beside them, is taken for hung. With virtual controller threads
     * ({@code -Dkheperasim.virtualThreads=true}, Java 24+) each such wait holds one of the carriers,
     * one per core: this is the case that option leaves out (docs/swarms.md), so it is not tested there.
     */
    @Test
    void controllersWaitingInsideClassInitializersDoNotStarveTheOthers() {
        org.junit.jupiter.api.Assumptions.assumeFalse(
                Runtime.version().feature() >= 24 && Boolean.getBoolean("kheperasim.virtualThreads"),
                "virtual controller threads: waits inside class initializers hold the carriers");
        Arena four = ArenaFormat.parse(ArenaFormat.write(THREE) + "robot 900 900 180\n", "four.arena");
        RunResult r = Simulation.builder().arena(four).controller("org.kheperasim.testcontrollers.Calibrating")
                .robot(3, "Braitenberg", null).seed(21).seconds(3).run();
        for (RunResult.RobotResult robot : r.robots()) {
            assertEquals(ControllerStatus.STOPPED, robot.status(), robot.name() + ": " + robot.failure());
            assertTrue(robot.distanceMm() > 10, robot.name() + " drove " + robot.distanceMm() + " mm");
        }
    }

    @Test
    void eachRobotRunsTheControllerAndSettingsItWasGiven() {
        StringWriter trace = new StringWriter();
        RunResult r = Simulation.builder().arena(THREE).controller("org.kheperasim.testcontrollers.Straight")
                .robot(1, "Braitenberg", null)
                .robot(2, null, org.kheperasim.sim.engine.model.Settings.defaults().with("motor.left.calibration", "0.5"))
                .seed(21).seconds(3).trace(trace).run();
        assertEquals(List.of("Straight#0", "Braitenberg#1", "Straight#2"),
                r.robots().stream().map(RunResult.RobotResult::name).toList());
        assertEquals(0, r.robots().get(0).headingDeg(), 10, "robot 0 drove about straight (its own calibration spread): " + r.robots().get(0));
        double turned = angleBetween(r.robots().get(2).headingDeg(), 180);
        assertTrue(turned > 30, "robot 2's worn left motor made it curve: turned " + turned + " deg");
        String header = trace.toString();
        assertTrue(header.contains("# robot-1 org.kheperasim.controllers.Braitenberg settings defaults"), header.lines().limit(12).toList().toString());
        assertTrue(header.contains("# robot-2 org.kheperasim.testcontrollers.Straight settings motor.left.calibration=0.5"),
                header.lines().limit(12).toList().toString());
    }

    private static double angleBetween(double a, double b) {
        double d = ((a - b) % 360 + 540) % 360 - 180;
        return StrictMath.abs(d);
    }

    /** A walled square with robots on a grid 200 mm apart, facing every which way, close enough to meet. */
    static Arena crowd(int n) {
        StringBuilder sb = new StringBuilder("khepera-arena 1\nname crowd\nsize 1219.2 1219.2\n"
                + "wall 0 4 1219.2 4 8\nwall 0 1215.2 1219.2 1215.2 8\nwall 4 0 4 1219.2 8\nwall 1215.2 0 1215.2 1219.2 8\n");
        for (int i = 0; i < n; i++) {
            sb.append("robot ").append(200 + (i % 5) * 200).append(' ').append(300 + (i / 5) * 200).append(' ')
                    .append((i * 77) % 360 - 180).append('\n');
        }
        return ArenaFormat.parse(sb.toString(), "crowd.arena");
    }

    @Test
    void tenRobotsThatMeetRepeatExactlyWithJitter() {
        StringWriter a = new StringWriter();
        StringWriter b = new StringWriter();
        RunResult first = Simulation.builder().arena(crowd(10)).controller("Braitenberg").seed(4).seconds(30).trace(a)
                .run();
        Simulation.builder().arena(crowd(10)).controller("Braitenberg").seed(4).seconds(30).trace(b)
                .hostOptions(HostOptions.defaults().withJitter(300)).run();
        assertEquals(a.toString(), b.toString(), "ten robots in lockstep give the same trace with jitter");
        assertEquals(10, first.robots().size());
        for (RunResult.RobotResult r : first.robots()) {
            assertTrue(r.distanceMm() > 200, r.name() + " drove " + r.distanceMm() + " mm");
        }
    }
}
