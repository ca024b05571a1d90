package org.kheperasim.link.protocol.dialect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.EpuckCommand;
import org.kheperasim.link.protocol.KheperaProtocol;
import org.kheperasim.link.protocol.ProtocolException;

/** The dialects: found by name, the Khepera I exactly today's protocol, the e-puck's letters both ways. */
class DialectTest {
    private final Dialect epuck = Dialect.named("epuck");

    @Test
    void dialectsAreFoundByNameAndAnUnknownNameListsTheKnownOnes() {
        assertSame(KheperaDialect.KHEPERA1, Dialect.named("khepera1"));
        assertSame(KheperaDialect.KHEPERA2, Dialect.named(" Khepera2 "));
        assertSame(EpuckDialect.EPUCK, epuck);
        assertEquals(Dialect.DEFAULT, Dialect.all().get(0).name());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Dialect.named("thymio"));
        assertEquals("dialect 'thymio' is not known; give one of khepera1, khepera2, epuck", e.getMessage());
    }

    @Test
    void theKheperaIIsTheKheperaIWithItsTwoFasterBauds() {
        assertEquals(List.of(9600, 19200, 38400), KheperaDialect.KHEPERA1.bauds());
        assertEquals(List.of(9600, 19200, 38400, 57600, 115200), KheperaDialect.KHEPERA2.bauds());
        assertEquals(KheperaDialect.KHEPERA1.letters(), KheperaDialect.KHEPERA2.letters());
        for (String line : List.of("D,3,-3", "H", "T,1,G", "B", "K", "W,1,2")) {
            assertEquals(KheperaProtocol.parseCommand(line), KheperaDialect.KHEPERA2.parseCommand(line));
        }
    }

    @Test
    void theKheperaIsErrorsAreTodays() {
        for (String line : List.of("Y", "D,1", "D,200,0", "x")) {
            ProtocolException e = assertThrows(ProtocolException.class, () -> KheperaDialect.KHEPERA1.parseCommand(line));
            assertEquals(KheperaProtocol.errorReply(e), KheperaDialect.KHEPERA1.errorReply(e));
        }
        assertEquals("z,Protocol error", KheperaDialect.KHEPERA1.overlongReply());
    }

    @Test
    void anEpuckControllerSpeaksTheEpucksLetters() {
        assertEquals("D,1000,-1000", epuck.setSpeeds(1000, -1000).encode());
        assertThrows(IllegalArgumentException.class, () -> epuck.setSpeeds(1001, 0));
        assertEquals("Q", epuck.readCounters().encode());
        assertEquals("q", epuck.readCounters().replyHead());
        assertEquals("P,5,6", epuck.setCounters(5, 6).encode());
        assertEquals("N", epuck.readProximity().encode());
        assertEquals("O", epuck.readLight().encode());
        assertEquals("E", epuck.readSpeeds().encode());
        assertEquals("V", epuck.version().encode());
        assertEquals(1000, epuck.maxSpeed());
        assertEquals("\r\n", epuck.replyEnd());
        assertEquals(List.of(115200), epuck.bauds());
        assertEquals(false, epuck.turrets());
    }

    @Test
    void anEpuckRepliesAreParsedAndItsRefusalIsCommandNotFound() {
        assertEquals(List.of("120", "-7"), epuck.parseReply(epuck.readCounters(), "q,120,-7\r\n").values());
        assertEquals("Version 1.1.3 September 2006",
                epuck.parseReply(epuck.version(), "v,Version 1.1.3 September 2006").values().get(0));
        ProtocolException e = assertThrows(ProtocolException.class,
                () -> epuck.parseReply(epuck.readCounters(), "z,Command not found"));
        assertEquals(ProtocolException.Kind.COMMAND_NOT_FOUND, e.kind());
        assertEquals(ProtocolException.Kind.WRONG_REPLY,
                assertThrows(ProtocolException.class, () -> epuck.parseReply(epuck.readCounters(), "h,1,2")).kind());
        assertTrue(epuck.looksLikeBanner("\f\007WELCOME to the SerCom protocol on e-Puck"));
        assertTrue(!epuck.looksLikeBanner("Khepera BIOS version 5.02"));
    }

    @Test
    void anEpuckServerReadsTheFirmwaresLines() {
        assertEquals(new EpuckCommand.SetSpeed(500, -500), epuck.parseCommand("D,500,-500\r"));
        assertEquals(new EpuckCommand.SetSpeed(10, 10), epuck.parseCommand("d,10,10"), "lower case is accepted");
        assertEquals(new Command.ReadProximity(), epuck.parseCommand("N,5"), "a read command's arguments are ignored");
        assertEquals(new EpuckCommand.ReadSteps(), epuck.parseCommand("Q"));
        assertEquals(new EpuckCommand.SetLed(8, 2), epuck.parseCommand("L,8,2"));
        assertEquals(new EpuckCommand.BodyLed(1), epuck.parseCommand("B,1"));
        assertInstanceOf(EpuckCommand.Help.class, epuck.parseCommand("H"));
        assertInstanceOf(EpuckCommand.Reset.class, epuck.parseCommand("R"));
        assertInstanceOf(EpuckCommand.Stop.class, epuck.parseCommand("S"));
        ProtocolException unknown = assertThrows(ProtocolException.class, () -> epuck.parseCommand("K"));
        assertEquals("z,Command not found", epuck.errorReply(unknown));
        ProtocolException bad = assertThrows(ProtocolException.class, () -> epuck.parseCommand("D,5"));
        assertEquals("d", epuck.errorReply(bad), "the firmware never refuses arguments: it acknowledges");
        assertEquals("z,Command not found", epuck.errorReply(
                assertThrows(ProtocolException.class, () -> epuck.parseCommand("T,1,G"))), "no turrets");
    }
}
