package org.kheperasim.sim.serve;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.engine.model.Settings;

/** Faults of the protocol server said out loud: an idle client is let go; a reconnect after a clean close is never refused. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
@Tag("timing")
class ServerFaultsTest {
    private static final Settings EXACT = Settings.defaults().withNoise(0);

    @Test
    void aClientThatClosesAndReconnectsAtOnceIsNeverRefused() throws Exception {
        try (Served s = new Served("", EXACT, 1)) {
            List<ProtocolServer.Event> events = new CopyOnWriteArrayList<>();
            s.server.addListener(events::add);
            for (int k = 0; k < 50; k++) {
                LineClient c = s.client();
                assertEquals("d", c.ask("D,1,1"), "reconnect " + k + " is served");
                c.close();
            }
            assertTrue(events.stream().noneMatch(e -> e.kind() == ProtocolServer.EventKind.REFUSED),
                    "no refusals: " + events.stream().filter(e -> e.kind() == ProtocolServer.EventKind.REFUSED).toList());
        }
    }

    @Test
    void aSecondClientIsStillRefusedWhileTheFirstStays() throws Exception {
        try (Served s = new Served("", EXACT, 1); LineClient first = s.client()) {
            assertEquals("d", first.ask("D,1,1"));
            try (LineClient second = s.client()) {
                String line = second.readLine();
                assertTrue(line != null && line.startsWith("z,Busy"), "refused after the hand-over wait: " + line);
            }
            assertEquals("d", first.ask("D,0,0"), "the first client keeps the robot");
        }
    }

    @Test
    void anIdleClientIsLetGoAndTheRobotStops() throws Exception {
        try (Served s = new Served("", EXACT, 1)) {
            s.server.idleTimeout(300);
            List<ProtocolServer.Event> events = new CopyOnWriteArrayList<>();
            s.server.addListener(events::add);
            try (LineClient idle = s.client()) {
                assertEquals("d", idle.ask("D,5,5"));
                String line = idle.readLine();
                assertTrue(line != null && line.startsWith("z,Idle"), "the idle client is told: " + line);
                assertNull(idle.readLine(), "and its connection closed");
            }
            // The slot is freed and the event told on the server's own thread: wait for both (a busy
            // machine may see the free slot before the listener has the event).
            long deadline = System.nanoTime() + 10_000_000_000L;
            while ((s.server.client() != null || events.stream().noneMatch(e -> e.text().contains("sent nothing")))
                    && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            assertNull(s.server.client(), "the slot is free");
            assertEquals(0, s.robot.snapshot().robots().get(0).speedLeft(), "the robot stopped");
            assertTrue(events.stream().anyMatch(e -> e.text().contains("sent nothing for 0.3 s")), "the console says why: " + events);
            try (LineClient next = s.client()) {
                assertEquals("d", next.ask("D,1,1"), "the next client is served");
            }
        }
    }
}
