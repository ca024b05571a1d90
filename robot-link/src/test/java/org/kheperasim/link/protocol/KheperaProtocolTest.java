package org.kheperasim.link.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.kheperasim.link.protocol.ProtocolException.Kind;

class KheperaProtocolTest {

    /** Every command of the reference: the typed command, its line, a reply line and the reply's values. */
    static Stream<Arguments> commands() {
        return Stream.of(
                Arguments.of(new Command.SetSpeedPid(3800, 800, 100), "A,3800,800,100", "a", List.of()),
                Arguments.of(new Command.ReadVersion(), "B", "b,5.02,5.01", List.of("5.02", "5.01")),
                Arguments.of(new Command.MoveToPosition(1000, -1000), "C,1000,-1000", "c", List.of()),
                Arguments.of(new Command.SetSpeed(3, -5), "D,3,-5", "d", List.of()),
                Arguments.of(new Command.ReadSpeed(), "E", "e,3,-5", List.of("3", "-5")),
                Arguments.of(new Command.SetPositionPid(3000, 20, 4000), "F,3000,20,4000", "f", List.of()),
                Arguments.of(new Command.SetPositionCounters(0, 0), "G,0,0", "g", List.of()),
                Arguments.of(new Command.ReadPositionCounters(), "H", "h,-2147483648,2147483647",
                        List.of("-2147483648", "2147483647")),
                Arguments.of(new Command.ReadAnalog(3), "I,3", "i,512", List.of("512")),
                Arguments.of(new Command.SetPositionProfile(20, 64, 20, 64), "J,20,64,20,64", "j", List.of()),
                Arguments.of(new Command.ReadMotionStatus(), "K", "k,1,0,0,1,0,0", List.of("1", "0", "0", "1", "0", "0")),
                Arguments.of(new Command.SetLed(1, 2), "L,1,2", "l", List.of()),
                Arguments.of(new Command.ReadProximity(), "N", "n,0,1,2,3,1020,1021,1022,1023",
                        List.of("0", "1", "2", "3", "1020", "1021", "1022", "1023")),
                Arguments.of(new Command.ReadLight(), "O", "o,480,470,20,21,499,500,450,451",
                        List.of("480", "470", "20", "21", "499", "500", "450", "451")),
                Arguments.of(new Command.SetPwm(-255, 255), "P,-255,255", "p", List.of()),
                Arguments.of(new Command.ReadBus(17), "R,17", "r,200", List.of("200")),
                Arguments.of(new Command.WriteBus(200, 17), "W,200,17", "w", List.of()),
                Arguments.of(Command.Turret.gripper(new TurretCommand.Fingers(false)), "T,1,D,0", "t,1,d", List.of()),
                Arguments.of(Command.Turret.gripper(new TurretCommand.Fingers(true)), "T,1,D,1", "t,1,d", List.of()),
                Arguments.of(Command.Turret.gripper(new TurretCommand.Arm(190)), "T,1,E,190", "t,1,e", List.of()),
                Arguments.of(Command.Turret.gripper(new TurretCommand.Resistivity()), "T,1,F", "t,1,f,120", List.of("120")),
                Arguments.of(Command.Turret.gripper(new TurretCommand.Barrier()), "T,1,G", "t,1,g,0", List.of("0")),
                Arguments.of(Command.Turret.gripper(new TurretCommand.MotorPosition(1)), "T,1,H,1", "t,1,h,250", List.of("250")),
                Arguments.of(Command.Turret.gripper(new TurretCommand.Version()), "T,1,B", "t,1,b,2,1", List.of("2", "1")),
                Arguments.of(Command.Turret.vision(new TurretCommand.Image()), "T,2,N", "t,2,n," + IMAGE, IMAGE_VALUES),
                Arguments.of(Command.Turret.vision(new TurretCommand.BrightestPixel()), "T,2,O", "t,2,o,63", List.of("63")),
                Arguments.of(Command.Turret.vision(new TurretCommand.DarkestPixel()), "T,2,P", "t,2,p,0", List.of("0")),
                Arguments.of(Command.Turret.vision(new TurretCommand.Version()), "T,2,B", "t,2,b,1,0", List.of("1", "0")),
                Arguments.of(new Command.Turret(2, new TurretCommand.Raw("U,3")), "T,2,U,3", "t,2,u", List.of()),
                Arguments.of(new Command.Turret(3, new TurretCommand.Raw("X,5,6")), "T,3,X,5,6", "t,3,x,9", List.of("9")));
    }

    /** A K213 image: 64 grey levels, a ramp from 0 to 252 in steps of 4. */
    private static final List<String> IMAGE_VALUES = java.util.stream.IntStream.range(0, 64)
            .mapToObj(i -> Integer.toString(4 * i)).toList();
    private static final String IMAGE = String.join(",", IMAGE_VALUES);

    @ParameterizedTest(name = "{1}")
    @MethodSource("commands")
    void encodesParsesAndAnswersEveryCommand(Command command, String line, String replyLine, List<String> values) {
        assertEquals(line, command.encode());
        assertEquals(command, KheperaProtocol.parseCommand(line), "parse " + line);
        assertEquals(command, KheperaProtocol.parseCommand(line + "\r"), "a CR-terminated command");
        assertEquals(command, KheperaProtocol.parseCommand(line + "\n"), "an LF-terminated command");
        Reply reply = KheperaProtocol.parseReply(command, replyLine + "\r\n");
        assertEquals(values, reply.values());
        assertEquals(replyLine, reply.encode(), "a server formats the same reply");
        assertEquals(replyLine, new Reply(command, values).encode());
    }

    @ParameterizedTest(name = "{1}")
    @MethodSource("commands")
    void everyCommandRecognisesTheRobotsErrors(Command command, String line) {
        ProtocolException unknown = assertThrows(ProtocolException.class,
                () -> KheperaProtocol.parseReply(command, "Command not found\r\n"));
        assertEquals(Kind.COMMAND_NOT_FOUND, unknown.kind());
        assertTrue(unknown.getMessage().contains("'" + line + "'"), unknown.getMessage());
        ProtocolException refused = assertThrows(ProtocolException.class,
                () -> KheperaProtocol.parseReply(command, "z,Protocol error"));
        assertEquals(Kind.ROBOT_ERROR, refused.kind());
        assertTrue(refused.getMessage().contains("'" + line + "'"), refused.getMessage());
    }

    static Stream<Arguments> wrongReplies() {
        return Stream.of(
                Arguments.of(new Command.ReadProximity(), "o,1,2,3,4,5,6,7,8", Kind.WRONG_REPLY),
                Arguments.of(new Command.ReadProximity(), "nonsense", Kind.WRONG_REPLY),
                Arguments.of(new Command.ReadProximity(), "", Kind.WRONG_REPLY),
                Arguments.of(new Command.ReadProximity(), "N", Kind.WRONG_REPLY),
                Arguments.of(new Command.ReadProximity(), "n,1,2,3", Kind.MALFORMED),
                Arguments.of(new Command.ReadProximity(), "n,1,2,3,4,5,6,7,x", Kind.MALFORMED),
                Arguments.of(new Command.ReadProximity(), "n,1,2,3,4,5,6,7,", Kind.MALFORMED),
                Arguments.of(new Command.ReadPositionCounters(), "h,99999999999,0", Kind.MALFORMED),
                Arguments.of(new Command.SetSpeed(1, 1), "d,5", Kind.MALFORMED),
                Arguments.of(new Command.ReadVersion(), "b,5.02", Kind.MALFORMED),
                Arguments.of(Command.Turret.gripper(new TurretCommand.Barrier()), "t,1,f,3", Kind.WRONG_REPLY),
                Arguments.of(Command.Turret.gripper(new TurretCommand.Barrier()), "t,2,g,3", Kind.WRONG_REPLY),
                Arguments.of(Command.Turret.gripper(new TurretCommand.Barrier()), "g,3", Kind.WRONG_REPLY));
    }

    @ParameterizedTest(name = "{0} <- ''{1}''")
    @MethodSource("wrongReplies")
    void refusesRepliesThatDoNotFit(Command command, String line, Kind kind) {
        ProtocolException e = assertThrows(ProtocolException.class, () -> KheperaProtocol.parseReply(command, line));
        assertEquals(kind, e.kind(), e.getMessage());
        assertTrue(e.getMessage().contains(command.encode()), "names the command: " + e.getMessage());
    }

    static Stream<Arguments> badCommandLines() {
        return Stream.of(
                Arguments.of("Q", Kind.UNKNOWN_COMMAND),
                Arguments.of("n", Kind.UNKNOWN_COMMAND),
                Arguments.of("", Kind.UNKNOWN_COMMAND),
                Arguments.of("DD,1,1", Kind.UNKNOWN_COMMAND),
                Arguments.of("D,1", Kind.BAD_ARGUMENTS),
                Arguments.of("D,1,2,3", Kind.BAD_ARGUMENTS),
                Arguments.of("D,128,0", Kind.BAD_ARGUMENTS),
                Arguments.of("D,a,b", Kind.BAD_ARGUMENTS),
                Arguments.of("N,1", Kind.BAD_ARGUMENTS),
                Arguments.of("L,2,0", Kind.BAD_ARGUMENTS),
                Arguments.of("P,300,0", Kind.BAD_ARGUMENTS),
                Arguments.of("T,1", Kind.BAD_ARGUMENTS),
                Arguments.of("T,1,D,2", Kind.BAD_ARGUMENTS),
                Arguments.of("T,1,E,300", Kind.BAD_ARGUMENTS),
                Arguments.of("T,x,G", Kind.BAD_ARGUMENTS));
    }

    @ParameterizedTest(name = "''{0}''")
    @MethodSource("badCommandLines")
    void aServerKnowsWhatToAnswerABadLine(String line, Kind kind) {
        ProtocolException e = assertThrows(ProtocolException.class, () -> KheperaProtocol.parseCommand(line));
        assertEquals(kind, e.kind(), e.getMessage());
        assertEquals(kind == Kind.UNKNOWN_COMMAND ? "Command not found" : "z,Protocol error", KheperaProtocol.errorReply(e));
    }

    @Test
    void rangesTheManualGivesAreCheckedWhenEncoding() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Command.SetSpeed(200, 0));
        assertTrue(e.getMessage().contains("200") && e.getMessage().contains("-127..127"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new TurretCommand.Arm(-1));
        assertThrows(IllegalArgumentException.class, () -> new Command.WriteBus(256, 0));
    }

    @Test
    void repliesCarryIntegersAndAServerFormatsThem() {
        Command n = new Command.ReadProximity();
        Reply r = n.reply(1, 2, 3, 4, 5, 6, 7, 1023);
        assertEquals("n,1,2,3,4,5,6,7,1023", r.encode());
        assertArrayEquals(new int[] {1, 2, 3, 4, 5, 6, 7, 1023}, KheperaProtocol.parseReply(n, r.encode()).ints());
        assertEquals("b,5.02,5.01", new Command.ReadVersion().reply("5.02", "5.01").encode());
        assertEquals("t,1,g,1", Command.Turret.gripper(new TurretCommand.Barrier()).reply(1).encode());
    }
}
