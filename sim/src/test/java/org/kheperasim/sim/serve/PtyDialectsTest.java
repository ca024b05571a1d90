package org.kheperasim.sim.serve;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.link.io.SerialLink;
import org.kheperasim.link.io.SerialSettings;
import org.kheperasim.link.protocol.dialect.Dialect;
import org.kheperasim.link.session.Session;
import org.kheperasim.link.timing.LinkTiming;
import org.kheperasim.sim.engine.model.Settings;

/**
 * Over {@code serve --pty}, in each dialect, a client of that dialect drives the robot: it opens
 * the pty as a serial port at the dialect's baud, asks the version with the dialect's command,
 * sets speeds with its {@code D}, reads the wheel counters with its own letter ({@code H} on a
 * Khepera, {@code Q} on an e-puck) and sees them grow, and the simulated robot has moved.
 *
 * <p>Tagged {@code timing}: real time over a pty, as the other pty tests.
 */
@Tag("timing")
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class PtyDialectsTest {
    @TempDir
    Path dir;

    @ParameterizedTest
    @ValueSource(strings = {"khepera1", "khepera2", "epuck"})
    void aClientOfTheDialectDrivesTheServedRobotOverThePty(String name) throws Exception {
        Dialect dialect = Dialect.named(name);
        int baud = dialect.bauds().get(dialect.bauds().size() - 1);
        Settings settings = Settings.defaults().with("link.baud", Integer.toString(baud));
        try (ServedDialectTest.InDialect served = new ServedDialectTest.InDialect(dialect, settings);
                PtyBridge bridge = PtyBridge.start(dir.resolve(name), served.server.port(), line -> { })) {
            SerialLink link = SerialLink.open(SerialSettings.khepera(bridge.link().toString(), baud));
            try (Session session = new Session(link, LinkTiming.atBaud(baud), Session.Options.defaults(), dialect)) {
                Session.Versions v = session.open();
                assertTrue(!v.bios().isEmpty(), name + ": the version answers " + v);
                double x0 = served.robot.inspect(r -> r.x());
                assertEquals(0, session.exchange(dialect.readCounters()).intValue(0));
                session.exchange(dialect.setSpeeds(10, 10));
                long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
                int counter = 0;
                while (counter < 100 && System.nanoTime() < until) {
                    Thread.sleep(20);
                    counter = session.exchange(dialect.readCounters()).intValue(0);
                }
                assertTrue(counter >= 100, name + ": the left counter grew to " + counter);
                session.exchange(dialect.setSpeeds(0, 0));
                assertEquals(0, session.exchange(dialect.readSpeeds()).intValue(0), name + ": stopped");
                double x1 = served.robot.inspect(r -> r.x());
                assertTrue(x1 > x0 + 1, name + ": the robot drove ahead, from x " + x0 + " to " + x1);
                assertEquals(8, session.exchange(dialect.readProximity()).values().size());
            }
        }
    }
}
