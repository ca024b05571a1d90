package org.kheperasim.sim.serve;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.view.Contact;

/**
 * Serving a whole arena: each robot answers on its own port, and two clients drive two robots that
 * meet in one world. The robots run on the wall clock (at speed x20), so the test waits for what it
 * expects with generous bounds instead of timing anything.
 */
@Tag("timing")
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ServedArenaTest {
    private static final Settings EXACT = Settings.defaults().withNoise(0);

    @Test
    void twoClientsDriveTwoServedRobotsIntoEachOtherAndBothStop() throws Exception {
        String text = "khepera-arena 1\nname two\nsize 1219.2 1219.2\nrobot 300 600 0\nrobot 500 600 180\n";
        try (ServedArena world = new ServedArena(ArenaFormat.parse(text, "two.arena"), EXACT, 1, 20)) {
            List<ServedRobot> robots = world.robots();
            assertEquals(2, robots.size());
            ProtocolServer a = ProtocolServer.start(robots.get(0), 0);
            ProtocolServer b = ProtocolServer.start(robots.get(1), 0);
            try (LineClient ca = new LineClient(a.port()); LineClient cb = new LineClient(b.port())) {
                assertTrue(a.port() != b.port(), "each robot has its own port");
                assertEquals("d", ca.ask("D,5,5"));
                assertEquals("d", cb.ask("D,5,5"));
                long deadline = System.nanoTime() + 60_000_000_000L;
                boolean bothBlocked = false;
                while (!bothBlocked && System.nanoTime() < deadline) {
                    Thread.sleep(50);
                    // Each client reads its own robot's sensors as it drives.
                    assertTrue(ca.ask("N").startsWith("n,"));
                    assertTrue(cb.ask("N").startsWith("n,"));
                    bothBlocked = robots.get(0).inspect(r -> r.blocked()) && robots.get(1).inspect(r -> r.blocked());
                }
                assertTrue(bothBlocked, "both robots were stopped by each other within 60 s");
                double x0 = robots.get(0).inspect(r -> r.x());
                double x1 = robots.get(1).inspect(r -> r.x());
                assertEquals(2 * RobotTypes.KHEPERA1.body().radiusMm(), x1 - x0, 0.05, "they touch and do not overlap");
                assertEquals(Contact.FRONT, robots.get(0).inspect(r -> r.contact()));
                assertEquals(Contact.FRONT, robots.get(1).inspect(r -> r.contact()));
                // Their wheels still turn (the clients asked for 5), but the encoders stall.
                String e1 = ca.ask("H");
                Thread.sleep(200);
                assertEquals(e1, ca.ask("H"), "robot 0's encoders stall at the contact");
                // The front sensors of each see the other.
                int front = Integer.parseInt(ca.ask("N").split(",")[3]);
                assertTrue(front > 500, "robot 0's front sensor sees robot 1: " + front);
            } finally {
                a.close();
                b.close();
            }
        }
    }
}
