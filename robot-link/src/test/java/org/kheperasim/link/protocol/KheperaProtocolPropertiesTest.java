package org.kheperasim.link.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.link.fuzz.Fuzz;
import org.kheperasim.link.fuzz.Mutations;

/**
 * Whatever the line, the codec returns a command (or reply) that encodes to one clean line and
 * parses back the same, or throws its own {@link ProtocolException} naming the line.
 */
@Tag("properties")
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class KheperaProtocolPropertiesTest {

    private static final List<String> LETTERS = List.of("A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K", "L", "N",
            "O", "P", "R", "W", "T", "M", "Z", "a", "d", "t", "", "TT", "\u00c9");
    private static final List<String> TURRET = List.of("D", "E", "F", "G", "H", "B", "X", "e", "1", "", "A,B", "Z\nD,9,9");
    private static final List<Command> COMMANDS = List.of(new Command.SetSpeedPid(1, 2, 3), new Command.ReadVersion(),
            new Command.MoveToPosition(1, 2), new Command.SetSpeed(3, -3), new Command.ReadSpeed(),
            new Command.ReadPositionCounters(), new Command.ReadAnalog(0), new Command.ReadMotionStatus(),
            new Command.ReadProximity(), new Command.ReadLight(), new Command.ReadBus(1),
            Command.Turret.gripper(new TurretCommand.Barrier()), Command.Turret.gripper(new TurretCommand.Version()),
            Command.Turret.gripper(new TurretCommand.Arm(190)), new Command.Turret(2, new TurretCommand.Raw("X,1")));

    static String commandLine(SplittableRandom r) {
        StringBuilder b = new StringBuilder(Mutations.pick(r, LETTERS));
        if (b.toString().equals("T") && r.nextInt(4) > 0) {
            b.append(',').append(Mutations.number(r, -1, 4)).append(',').append(Mutations.pick(r, TURRET));
        }
        for (int i = 0, n = r.nextInt(6); i < n; i++) {
            b.append(',').append(r.nextInt(3) == 0 ? Mutations.pick(r, Mutations.EDGE_NUMBERS) : Integer.toString(r.nextInt(600) - 300));
        }
        String line = b.toString();
        line = r.nextInt(3) == 0 ? Mutations.damage(r, line, List.of(",", "T,1,", "\r", "\n"), 2) : line;
        return line + Mutations.pick(r, List.of("", "", "\r", "\n", "\r\n"));
    }

    static void commandParsesAndEncodesAsOneLine(String line) {
        Command c;
        try {
            c = KheperaProtocol.parseCommand(line);
        } catch (ProtocolException e) {
            assertEquals(KheperaProtocol.stripEnd(line), e.line());
            assertTrue(e.kind() == ProtocolException.Kind.UNKNOWN_COMMAND || e.kind() == ProtocolException.Kind.BAD_ARGUMENTS,
                    e.kind().toString());
            return;
        }
        String encoded = c.encode();
        assertTrue(encoded.chars().allMatch(ch -> ch >= 0x20 && ch <= 0x7E), "one printable line: " + Fuzz.visible(encoded));
        assertEquals(c, KheperaProtocol.parseCommand(encoded), "parses back");
    }

    record ReplyCase(Command command, String line) {
    }

    static ReplyCase reply(SplittableRandom r) {
        Command c = Mutations.pick(r, COMMANDS);
        StringBuilder b = new StringBuilder(r.nextInt(10) == 0 ? Mutations.pick(r, List.of("z", "z,Protocol error",
                "Command not found", "x", "t,1", "")) : c.replyHead());
        int n = c.replyValueCount() >= 0 && r.nextInt(4) > 0 ? c.replyValueCount() : r.nextInt(10);
        for (int i = 0; i < n; i++) {
            b.append(',').append(r.nextInt(3) == 0 ? Mutations.pick(r, Mutations.EDGE_NUMBERS) : Integer.toString(r.nextInt(2048) - 1024));
        }
        String line = r.nextInt(4) == 0 ? Mutations.damage(r, b.toString(), List.of(",", "\r", "5.02"), 2) : b.toString();
        return new ReplyCase(c, line + Mutations.pick(r, List.of("", "\r\n", "\r", "\n")));
    }

    static void replyParsesAndEncodesAsOneLine(ReplyCase rc) {
        Reply reply;
        try {
            reply = KheperaProtocol.parseReply(rc.command(), rc.line());
        } catch (ProtocolException e) {
            assertEquals(KheperaProtocol.stripEnd(rc.line()), e.line());
            return;
        }
        if (rc.command().replyValueCount() >= 0) {
            assertEquals(rc.command().replyValueCount(), reply.values().size());
        }
        String encoded = reply.encode();
        assertTrue(encoded.chars().allMatch(ch -> ch >= 0x20 && ch <= 0x7E), "one printable line: " + Fuzz.visible(encoded));
        assertEquals(reply, KheperaProtocol.parseReply(rc.command(), encoded));
        if (rc.command().integerReply()) {
            reply.ints();
        }
    }

    @Test
    void everyCommandLineParsesToACommandThatEncodesAsOneLineOrIsRefused() {
        Fuzz.checkText("protocol command", 5000, KheperaProtocolPropertiesTest::commandLine,
                KheperaProtocolPropertiesTest::commandParsesAndEncodesAsOneLine);
    }

    @Test
    void everyReplyLineParsesToAReplyThatEncodesAsOneLineOrIsRefused() {
        Fuzz.check("protocol reply", 5000, KheperaProtocolPropertiesTest::reply,
                KheperaProtocolPropertiesTest::replyParsesAndEncodesAsOneLine,
                rc -> {
                    List<ReplyCase> out = new ArrayList<>();
                    for (int i = rc.line().length() - 1; i >= 0; i--) {
                        out.add(new ReplyCase(rc.command(), rc.line().substring(0, i) + rc.line().substring(i + 1)));
                    }
                    return out;
                }, rc -> rc.command().encode() + " <- " + Fuzz.visible(rc.line()));
    }

    /** Issue 14: a line break inside a raw turret command went on the wire as two commands. */
    @Test
    void aLineBreakInsideARawTurretCommandIsRefused() {
        ProtocolException e = assertThrows(ProtocolException.class, () -> KheperaProtocol.parseCommand("T,2,A\nD,127,127"));
        assertEquals(ProtocolException.Kind.BAD_ARGUMENTS, e.kind());
        assertTrue(e.getMessage().contains("U+000A at position 2"), e.getMessage());
        assertThrows(ProtocolException.class, () -> KheperaProtocol.parseCommand("T,2,A\rD,127,127"));
        assertThrows(IllegalArgumentException.class, () -> new TurretCommand.Raw("A\u0000"));
        assertThrows(IllegalArgumentException.class, () -> new TurretCommand.Raw("\u00c9,1"));
        assertEquals("T,2,A,1", KheperaProtocol.parseCommand("T,2,A,1\r\n").encode(), "a line's own end is not part of it");
        ProtocolException reply = assertThrows(ProtocolException.class,
                () -> KheperaProtocol.parseReply(new Command.ReadVersion(), "b,5.02\r,5.01"));
        assertEquals(ProtocolException.Kind.MALFORMED, reply.kind());
    }
}
