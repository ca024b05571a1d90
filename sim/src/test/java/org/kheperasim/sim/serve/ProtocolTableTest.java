package org.kheperasim.sim.serve;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.view.RobotView;

/**
 * Every command of the reference against the served robot, over TCP, with the replies a real
 * Khepera gives. The robot stands at (300, 600) facing +x, its front 9.5 mm from a wall.
 */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
@Tag("timing")
class ProtocolTableTest {
    private static final Settings EXACT = Settings.defaults().withNoise(0);
    /** A wall across the robot's path, its face at x = 337: 9.5 mm from the body, 12 mm from the front sensors. */
    private static final String WALL_AHEAD = "wall 341 400 341 800 8\n";

    private static int[] values(String reply, String head, int count) {
        assertTrue(reply.startsWith(head + ","), "reply '" + reply + "' starts with " + head);
        int[] v = Arrays.stream(reply.substring(head.length() + 1).split(",")).mapToInt(Integer::parseInt).toArray();
        assertEquals(count, v.length, reply);
        return v;
    }

    @Test
    void eachCommandGetsTheRobotsReply() throws Exception {
        try (Served s = new Served(WALL_AHEAD, EXACT, 1); LineClient c = s.client()) {
            int[] n = values(c.ask("N"), "n", 8);
            assertTrue(n[2] > 600 && n[3] > 600, "the wall 12 mm ahead reads high in front: " + Arrays.toString(n));
            for (int i : new int[] {0, 5, 6, 7}) {
                assertTrue(n[i] < 100, "nothing beside or behind: sensor " + i + " " + Arrays.toString(n));
            }
            int[] o = values(c.ask("O"), "o", 8);
            for (int v : o) {
                assertTrue(v >= 400 && v <= 520, "no lamp: the dark reading, about 450-500: " + Arrays.toString(o));
            }
            String[][] table = {
                {"B", "b,5.02,5.01"},
                {"A,3800,800,100", "a"},
                {"F,3000,20,4000", "f"},
                {"E", "e,0,0"},
                {"D,5,-5", "d"},
                {"E", "e,5,-5"},
                {"K", "k,1,0,0,1,0,0"},
                {"D,0,0", "d"},
                {"G,100,200", "g"},
                {"H", "h,100,200"},
                {"I,0", "i,0"},
                {"W,42,7", "w"},
                {"R,7", "r,42"},
                {"R,8", "r,0"},
                {"P,100,-255", "p"},
                {"E", "e,50,-127"},
                {"K", "k,1,2,0,1,2,0"},
                {"D,0,0", "d"},
                {"J,20,64,20,64", "j"},
                {"L,0,1", "l"},
                // errors, as the robot answers them
                {"Q", "Command not found"},
                {"d,1,1", "Command not found"},
                {"DD,1,1", "Command not found"},
                {"D,1", "z,Protocol error"},
                {"D,200,0", "z,Protocol error"},
                {"D,a,b", "z,Protocol error"},
                {"L,5,1", "z,Protocol error"},
                {"B,1", "z,Protocol error"},
                {"T,2,B", "t,2,b,1,0"},
                {"T,2,Z", "Command not found"},
                {"T,2,N,1", "z,Protocol error"},
                {"T,3,B", "Command not found"},
                {"T,1,Z", "Command not found"},
                {"T,1", "z,Protocol error"},
                {"T,1,E,300", "z,Protocol error"},
            };
            for (String[] row : table) {
                assertEquals(row[1], c.ask(row[0]), "reply to " + row[0]);
            }
            assertEquals(1, s.robot.snapshot().robots().get(0).leds(), "L,0,1 lit the lateral LED");
            assertEquals("l", c.ask("L,1,2"));
            assertEquals(3, s.robot.snapshot().robots().get(0).leds(), "L,1,2 toggled the front LED on");
            assertEquals("l", c.ask("L,0,0"));
            assertEquals(2, s.robot.snapshot().robots().get(0).leds());

        }
    }

    @Test
    void theWorldsSnapshotShowsWhatTheServedRobotLastReported() throws Exception {
        // The window's sensor panel draws a served robot from snapshots: it shows the values of the
        // client's last N and O, not those the robot had before it was served.
        try (Served s = new Served(WALL_AHEAD + "light 300 680\n", Settings.defaults(), 1); LineClient c = s.client()) {
            int[] n = values(c.ask("N"), "n", 8);
            int[] o = values(c.ask("O"), "o", 8);
            RobotView seen = s.robot.snapshot().robots().get(0);
            assertArrayEquals(n, seen.proximity(), "proximity: " + Arrays.toString(seen.proximity()));
            assertArrayEquals(o, seen.light(), "light: " + Arrays.toString(seen.light()));
            int[] again = values(c.ask("N"), "n", 8);
            assertArrayEquals(again, s.robot.snapshot().robots().get(0).proximity(), "the next N replaces them");
        }
    }

    @Test
    void aPositionMoveFollowsTheTrapezoidAndKReportsIt() throws Exception {
        try (Served s = new Served("", EXACT, 1); LineClient c = s.client()) {
            assertEquals("g", c.ask("G,0,0"));
            assertEquals("j", c.ask("J,10,64,10,64"));
            long start = System.nanoTime();
            // The speed profile is watched in robot time (every 10 ms), which load cannot thin out: the
            // fastest speed, and when the wheels first turned and last turned.
            java.util.concurrent.atomic.AtomicInteger fastest = new java.util.concurrent.atomic.AtomicInteger();
            java.util.concurrent.atomic.AtomicLong firstMoving = new java.util.concurrent.atomic.AtomicLong(-1);
            java.util.concurrent.atomic.AtomicLong lastMoving = new java.util.concurrent.atomic.AtomicLong(-1);
            s.robot.addListener(snap -> {
                int speed = snap.robots().get(0).speedLeft();
                fastest.accumulateAndGet(speed, Math::max);
                if (speed != 0) {
                    firstMoving.compareAndSet(-1, snap.timeNanos());
                    lastMoving.set(snap.timeNanos());
                }
            }, 10_000_000L);
            assertEquals("c", c.ask("C,500,-500"));
            int[] k = values(c.ask("K"), "k", 6);
            assertEquals(0, k[0], "left not on target yet: " + Arrays.toString(k));
            assertEquals(1, k[1], "left in position mode");
            assertTrue(k[2] > 400 && k[2] <= 500, "left error in pulses: " + Arrays.toString(k));
            assertEquals(1, k[4], "right in position mode");
            assertTrue(k[5] < -400, "right error: " + Arrays.toString(k));
            int maxSpeed = 0;
            while (true) {
                int[] e = values(c.ask("E"), "e", 2);
                maxSpeed = Math.max(maxSpeed, e[0]);
                assertEquals(-e[0], e[1], "a spin on the spot: opposite speeds");
                k = values(c.ask("K"), "k", 6);
                if (k[0] == 1 && k[3] == 1) {
                    break;
                }
                assertTrue(System.nanoTime() - start < 30e9, "the move ends: " + Arrays.toString(k));
            }
            // In robot time, from the robot's own snapshots, which a loaded machine cannot stretch (a
            // client slowed by load only sees the end later): 500 pulses at most 10 pulses/10 ms,
            // accelerating 64/256 pulse/10 ms per 10 ms: 0.4 s up (200 pulses), 0.1 s at 10 (100),
            // 0.4 s down (200) = 0.9 s.
            double seconds = (lastMoving.get() - firstMoving.get()) / 1e9;
            assertTrue(seconds > 0.75 && seconds < 1.5, "the trapezoid takes about 0.9 s of robot time (the move is"
                    + " updated every 10 ms and counts as done within half a pulse): " + seconds);
            assertTrue(maxSpeed <= 10, "E never reports more than the profile's maximum: " + maxSpeed);
            assertEquals(10, fastest.get(), "the profile's maximum speed is reached and not exceeded");
            int[] h = values(c.ask("H"), "h", 2);
            assertEquals(500, h[0], 1);
            assertEquals(-500, h[1], 1);
            assertEquals("e,0,0", c.ask("E"), "at rest on target");
            assertEquals("d", c.ask("D,3,3"));
            assertEquals("k,1,0,0,1,0,0", c.ask("K"), "D leaves position mode");
        }
    }

    @Test
    void theGripperTurretAnswersAndActs() throws Exception {
        double gripX = 300 + 36.5;
        try (Served s = new Served("cap " + gripX + " 600\n", EXACT, 4); LineClient c = s.client()) {
            assertEquals("t,1,b,2,1", c.ask("T,1,B"));
            assertEquals("t,1,h,180", c.ask("T,1,H,1"), "the arm starts up");
            assertEquals("t,1,g,0", c.ask("T,1,G"), "arm up: the barrier passes above the cap");
            assertEquals("t,1,e", c.ask("T,1,E,250"));
            waitFor(c, "T,1,H,1", "t,1,h,250");
            assertEquals("t,1,g,255", c.ask("T,1,G"), "arm down: the cap breaks the barrier");
            assertEquals("t,1,f,0", c.ask("T,1,F"), "nothing held yet");
            assertEquals("t,1,h,0", c.ask("T,1,H,0"), "fingers open");
            assertEquals("t,1,d", c.ask("T,1,D,1"));
            waitFor(c, "T,1,H,0", "t,1,h,255");
            assertEquals("t,1,f,120", c.ask("T,1,F"), "a held cap reads the cap's resistivity");
            assertEquals(0, (int) s.robot.inspect(r -> r.gripper().heldCap()));
            assertEquals("t,1,d", c.ask("T,1,D,0"));
            waitFor(c, "T,1,H,0", "t,1,h,0");
            assertEquals(-1, (int) s.robot.inspect(r -> r.gripper().heldCap()), "opening drops it");
        }
    }

    private static void waitFor(LineClient c, String command, String reply) throws Exception {
        long end = System.nanoTime() + 5_000_000_000L;
        String last;
        while (!(last = c.ask(command)).equals(reply)) {
            assertTrue(System.nanoTime() < end, command + " never answered " + reply + "; last " + last);
            Thread.sleep(10);
        }
    }

    /**
     * Tagged {@code realtime}: a reply's lateness on the wall clock (the best of 30 within 3 ms, the median within
     * 50 ms) holds on an idle machine and beside two busy loops, not at load 30 on 2 cores; the default
     * {@code mvn -B verify} leaves it out and {@code .ci/run}'s busy pass runs it.
     */
    @Test
    @Tag("realtime")
    void repliesArriveAtTheirWireTimeAtTheSetBaud() throws Exception {
        for (int baud : new int[] {9600, 38400}) {
            Settings settings = EXACT.with("link.baud", Integer.toString(baud));
            LinkTiming timing = LinkTiming.atBaud(baud);
            try (Served s = new Served(WALL_AHEAD, settings, 1); LineClient c = s.client()) {
                c.ask("B");
                int rounds = 30;
                long[] late = new long[rounds];
                for (int i = 0; i < rounds; i++) {
                    long t0 = System.nanoTime();
                    String reply = c.ask("N");
                    long rtt = System.nanoTime() - t0;
                    late[i] = rtt - timing.exchangeNanos(2, reply.length() + 2);
                }
                Arrays.sort(late);
                // Exact: no reply ever comes before its wire time. A loaded machine can only delay
                // replies, so the rest is judged on the best of them and, generously, the median.
                assertTrue(late[0] >= 0, baud + " baud: no reply comes before its wire time; earliest by "
                        + late[0] / 1e6 + " ms");
                assertTrue(late[0] < 3_000_000L, baud + " baud: unhindered, a reply comes at its wire time; the"
                        + " best of " + rounds + " was late by " + late[0] / 1e6 + " ms");
                assertTrue(late[rounds / 2] < 50_000_000L, baud + " baud: median lateness " + late[rounds / 2] / 1e6 + " ms");
                System.out.printf(java.util.Locale.ROOT, "N round trip at %d baud: wire time %.2f ms, lateness best %.3f ms, median %.3f ms%n",
                        baud, timing.exchangeNanos(2, 40) / 1e6, late[0] / 1e6, late[rounds / 2] / 1e6);
            }
        }
    }
}
