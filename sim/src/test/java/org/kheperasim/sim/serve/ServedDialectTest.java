package org.kheperasim.sim.serve;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.link.fake.Transcript;
import org.kheperasim.link.io.LineEnd;
import org.kheperasim.link.io.TcpLink;
import org.kheperasim.link.protocol.dialect.Dialect;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.engine.model.Settings;

/**
 * {@code serve} answers in a dialect: the recorded transcript of each dialect (robot-link's test
 * resources, from the manuals and the e-puck's firmware) replays against the served robot, as it
 * does against the fakes; the Khepera I's is served by default.
 */
@Timeout(120)
class ServedDialectTest {
    static final String ARENA = "khepera-arena 1\nname t\nsize 1219.2 1219.2\nrobot 300 600 0\n";

    /** A lone robot served in {@code dialect} (null: the default), and its server. */
    static final class InDialect implements AutoCloseable {
        final ServedArena world;
        final ServedRobot robot;
        final ProtocolServer server;

        InDialect(Dialect dialect, Settings settings) throws IOException {
            world = new ServedArena(ArenaFormat.parse(ARENA, "t.arena"), settings, 1, 1);
            if (dialect != null) {
                world.dialect(dialect);
            }
            robot = world.robots().get(0);
            server = ProtocolServer.start(robot, 0);
        }

        @Override
        public void close() {
            server.close();
            world.close();
        }
    }

    private static int replay(Dialect dialect, String transcript) throws IOException {
        try (InDialect served = new InDialect(dialect, Settings.defaults());
                TcpLink link = TcpLink.connect("127.0.0.1", served.server.port(), LineEnd.LF, 5000)) {
            return Transcript.load(transcript).replay(link, 2000);
        }
    }

    @Test
    void theKheperaITranscriptReplaysAgainstServeByDefault() throws IOException {
        assertEquals(Transcript.load("khepera1").exchanges().size(), replay(null, "khepera1"));
        assertEquals(Transcript.load("khepera1").exchanges().size(), replay(Dialect.named("khepera1"), "khepera1"));
    }

    @Test
    void theKheperaIITranscriptReplaysAgainstServeDialectKhepera2() throws IOException {
        assertEquals(Transcript.load("khepera2").exchanges().size(), replay(Dialect.named("khepera2"), "khepera2"));
    }

    @Test
    void theEpuckTranscriptReplaysAgainstServeDialectEpuck() throws IOException {
        assertTrue(replay(Dialect.named("epuck"), "epuck") >= 20);
    }

    @Test
    void theDialectDecidesTheLettersTheErrorsAndTheLineEnds() throws IOException {
        try (InDialect served = new InDialect(Dialect.named("epuck"), Settings.defaults());
                LineClient c = new LineClient(served.server.port())) {
            assertEquals("z,Command not found", c.ask("K"));
            assertEquals("d", c.ask("D,5"), "the e-puck acknowledges arguments it cannot use");
            assertEquals("z,Command not found", c.ask("x".repeat(ProtocolServer.MAX_LINE_CHARS + 5)));
        }
        try (InDialect served = new InDialect(null, Settings.defaults());
                LineClient c = new LineClient(served.server.port())) {
            assertEquals("Command not found", c.ask("Q"), "the Khepera has no Q");
            assertEquals("z,Protocol error", c.ask("D,5"));
        }
    }

    @Test
    void theEpucksLedsAndStepCountersReachTheRobot() throws IOException {
        try (InDialect served = new InDialect(Dialect.named("epuck"), Settings.defaults());
                LineClient c = new LineClient(served.server.port())) {
            assertEquals("l", c.ask("L,8,1"));
            assertEquals(0xFF, (int) served.robot.<Integer>inspect(r -> r.onBoard().leds()), "L,8,1: all eight ring LEDs");
            assertEquals("b", c.ask("B,1"));
            assertEquals(0x1FF, (int) served.robot.<Integer>inspect(r -> r.onBoard().leds()));
            assertEquals("p", c.ask("P,40,-40"));
            assertEquals("q,40,-40", c.ask("Q"));
            assertEquals("s", c.ask("S"));
            assertEquals(0, (int) served.robot.<Integer>inspect(r -> r.onBoard().leds()), "S turns the LEDs off");
        }
    }

    @Test
    void anEpuckInTheArenaAnswersAsAnEpuckWithoutBeingTold() throws IOException {
        // The robot's type chooses its dialect (its robot file's "dialect: epuck"); the Khepera beside it keeps its own.
        String arena = "khepera-arena 1\nname t\nsize 1219.2 1219.2\nrobot 300 600 0 epuck\nrobot 900 600 180\n";
        try (ServedArena world = new ServedArena(ArenaFormat.parse(arena, "t.arena"), Settings.defaults(), 1, 1)) {
            ProtocolServer epuck = ProtocolServer.start(world.robots().get(0), 0);
            ProtocolServer khepera = ProtocolServer.start(world.robots().get(1), 0);
            try (LineClient e = new LineClient(epuck.port()); LineClient k = new LineClient(khepera.port())) {
                assertTrue(e.ask("V").startsWith("v,Version"), "the e-puck names its SerCom firmware");
                assertEquals("q,0,0", e.ask("Q"), "the e-puck's step counters");
                assertEquals("Command not found", k.ask("Q"), "the Khepera has no Q");
                assertTrue(k.ask("B").startsWith("b,"), "the Khepera's BIOS version");
            } finally {
                epuck.close();
                khepera.close();
            }
        }
    }
}
