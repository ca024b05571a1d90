package org.kheperasim.sim.engine.sensing;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.space.World;

/**
 * The robot's own 20 ms scan: whatever reads a sensor (here a protocol client's {@code N} and
 * {@code O}, read on the robot) gets the latest scan, which is the world at the last 20 ms boundary,
 * never anything newer; two reads within one scan period answer the same values; and a scan nobody
 * reads costs nothing and shifts no other scan's draws.
 */
class ScanTest {
    /** A robot driving toward a wall 70 mm ahead (a lamp beyond it): its front sensors' readings change every scan. */
    private static final String ARENA = "khepera-arena 1\nname t\nsize 1219.2 1219.2\nrobot 380 600 0\n"
            + "wall 0 4 1219.2 4 8\nwall 0 1215.2 1219.2 1215.2 8\nwall 4 0 4 1219.2 8\nwall 1215.2 0 1215.2 1219.2 8\n"
            + "light 700 600\nwall 480 300 480 900 8\n";

    private static SimRobot robot(Engine e) {
        SimRobot r = e.addRobot("r", new Pose(380, 600, 0), Settings.defaults());
        r.onBoard().servedDirectly();
        r.onBoard().driveSpeeds(3, 3);
        return r;
    }

    private static Engine engine() {
        return new Engine(new World(ArenaFormat.parse(ARENA, "t.arena")), 11);
    }

    /** @return the proximity and light values read on the robot at {@code millis} */
    private static int[] readAt(Engine e, SimRobot r, long millis) {
        e.runUntil(millis * Engine.TICK_NANOS);
        int[] prox = new int[8];
        int[] light = new int[8];
        r.onBoard().readProximity(prox);
        r.onBoard().readLight(light);
        int[] both = Arrays.copyOf(prox, 16);
        System.arraycopy(light, 0, both, 8, 8);
        return both;
    }

    @Test
    void twoReadsWithinOneScanAnswerTheSameValuesAndAReadCarriesTheLastBoundarysScan() {
        Engine anyTime = engine();
        SimRobot a = robot(anyTime);
        Engine atBoundaries = engine();
        SimRobot b = robot(atBoundaries);
        int changed = 0;
        int[] previous = null;
        for (long window = 1; window < 100; window++) {
            long boundary = window * 20;
            // The second robot is read at the boundary itself: the scan taken there.
            int[] scan = readAt(atBoundaries, b, boundary);
            // The first, at four moments inside the window: the same values each time, the boundary's.
            for (long into : new long[] {1, 7, 13, 19}) {
                assertArrayEquals(scan, readAt(anyTime, a, boundary + into), "window " + window + ", " + into + " ms in:"
                        + " a read carries the scan of the last 20 ms boundary, nothing newer");
            }
            if (previous != null && !Arrays.equals(previous, scan)) {
                changed++;
            }
            previous = scan;
        }
        // The readings do change from scan to scan (the robot drives toward a wall and a lamp; noise is redrawn).
        assertTrue(changed > 90, "the values changed between scans " + changed + " times of 98");
    }

    @Test
    void aScanNobodyReadsCostsNothingAndShiftsNoOtherScansDraws() {
        Engine everyScan = engine();
        SimRobot a = robot(everyScan);
        Engine everyThird = engine();
        SimRobot b = robot(everyThird);
        List<String> read = new ArrayList<>();
        for (long window = 1; window < 60; window++) {
            int[] all = readAt(everyScan, a, window * 20 + 5);
            if (window % 3 == 0) {
                assertArrayEquals(all, readAt(everyThird, b, window * 20 + 5), "window " + window);
                read.add(Arrays.toString(all));
            }
        }
        assertEquals(19, read.size());
        assertNotEquals(read.get(0), read.get(1));
    }
}
