package org.kheperasim.link.protocol;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.kheperasim.link.protocol.ProtocolException.Kind;

/**
 * Parsing both ways of the Khepera I/II protocol. A client encodes a {@link Command} and parses the
 * reply with {@link #parseReply}; a server (a simulator answering like a robot) parses the command
 * line with {@link #parseCommand}, answers with {@link Command#reply} or, when the line is wrong,
 * with {@link #errorReply}.
 *
 * <p>Lines are handled without their terminators: a command ends with exactly one CR or LF, a reply
 * with CR LF ({@link #REPLY_END}).
 */
public final class KheperaProtocol {
    /** The robot's answer to an unknown command letter (no {@code z,} prefix). */
    public static final String COMMAND_NOT_FOUND = "Command not found";
    /** The answer to a known letter with wrong arguments (emulator evidence only). */
    public static final String PROTOCOL_ERROR = "z,Protocol error";
    /** What ends every reply line. */
    public static final String REPLY_END = "\r\n";

    private KheperaProtocol() {
    }

    /**
     * Parse a command line as the robot receives it.
     *
     * @param line one command, with or without its CR/LF terminator
     * @return the typed command
     * @throws ProtocolException {@link Kind#UNKNOWN_COMMAND} for an unknown letter (answer
     *     {@link #COMMAND_NOT_FOUND}), {@link Kind#BAD_ARGUMENTS} for a known letter with wrong
     *     arguments (answer {@link #PROTOCOL_ERROR})
     */
    public static Command parseCommand(String line) {
        String text = stripEnd(line);
        String[] parts = text.split(",", -1);
        if (parts[0].length() != 1 || !Character.isUpperCase(parts[0].charAt(0))) {
            throw new ProtocolException(Kind.UNKNOWN_COMMAND, text,
                    "'" + text + "' is not a Khepera command: a command is an upper-case letter and"
                            + " comma-separated integers, e.g. D,3,3");
        }
        char letter = parts[0].charAt(0);
        try {
            return switch (letter) {
                case 'A' -> { int[] a = ints(text, parts, 3); yield new Command.SetSpeedPid(a[0], a[1], a[2]); }
                case 'B' -> { ints(text, parts, 0); yield new Command.ReadVersion(); }
                case 'C' -> { int[] a = ints(text, parts, 2); yield new Command.MoveToPosition(a[0], a[1]); }
                case 'D' -> { int[] a = ints(text, parts, 2); yield new Command.SetSpeed(a[0], a[1]); }
                case 'E' -> { ints(text, parts, 0); yield new Command.ReadSpeed(); }
                case 'F' -> { int[] a = ints(text, parts, 3); yield new Command.SetPositionPid(a[0], a[1], a[2]); }
                case 'G' -> { int[] a = ints(text, parts, 2); yield new Command.SetPositionCounters(a[0], a[1]); }
                case 'H' -> { ints(text, parts, 0); yield new Command.ReadPositionCounters(); }
                case 'I' -> { int[] a = ints(text, parts, 1); yield new Command.ReadAnalog(a[0]); }
                case 'J' -> {
                    int[] a = ints(text, parts, 4);
                    yield new Command.SetPositionProfile(a[0], a[1], a[2], a[3]);
                }
                case 'K' -> { ints(text, parts, 0); yield new Command.ReadMotionStatus(); }
                case 'L' -> { int[] a = ints(text, parts, 2); yield new Command.SetLed(a[0], a[1]); }
                case 'N' -> { ints(text, parts, 0); yield new Command.ReadProximity(); }
                case 'O' -> { ints(text, parts, 0); yield new Command.ReadLight(); }
                case 'P' -> { int[] a = ints(text, parts, 2); yield new Command.SetPwm(a[0], a[1]); }
                case 'R' -> { int[] a = ints(text, parts, 1); yield new Command.ReadBus(a[0]); }
                case 'W' -> { int[] a = ints(text, parts, 2); yield new Command.WriteBus(a[0], a[1]); }
                case 'T' -> parseTurret(text, parts);
                default -> throw new ProtocolException(Kind.UNKNOWN_COMMAND, text,
                        "'" + text + "': the Khepera has no command " + letter);
            };
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(Kind.BAD_ARGUMENTS, text, "'" + text + "': " + e.getMessage());
        }
    }

    private static Command parseTurret(String text, String[] parts) {
        if (parts.length < 3 || parts[2].isEmpty()) {
            throw new ProtocolException(Kind.BAD_ARGUMENTS, text,
                    "'" + text + "': a turret command is T,id,<command>, e.g. T,1,G");
        }
        int id = integer(text, parts[1]);
        String body = String.join(",", Arrays.copyOfRange(parts, 2, parts.length));
        String[] inner = Arrays.copyOfRange(parts, 2, parts.length);
        if (id == Command.Turret.GRIPPER && inner[0].length() == 1) {
            TurretCommand typed = switch (inner[0].charAt(0)) {
                case 'D' -> {
                    int v = ints(text, inner, 1)[0];
                    if (v != 0 && v != 1) {
                        throw new IllegalArgumentException("fingers " + v + " must be 0 (open) or 1 (close)");
                    }
                    yield new TurretCommand.Fingers(v == 1);
                }
                case 'E' -> new TurretCommand.Arm(ints(text, inner, 1)[0]);
                case 'F' -> { ints(text, inner, 0); yield new TurretCommand.Resistivity(); }
                case 'G' -> { ints(text, inner, 0); yield new TurretCommand.Barrier(); }
                case 'H' -> new TurretCommand.MotorPosition(ints(text, inner, 1)[0]);
                case 'B' -> { ints(text, inner, 0); yield new TurretCommand.Version(); }
                default -> null;
            };
            if (typed != null) {
                return new Command.Turret(id, typed);
            }
        }
        if (id == Command.Turret.VISION && inner[0].length() == 1) {
            TurretCommand typed = switch (inner[0].charAt(0)) {
                case 'N' -> { ints(text, inner, 0); yield new TurretCommand.Image(); }
                case 'O' -> { ints(text, inner, 0); yield new TurretCommand.BrightestPixel(); }
                case 'P' -> { ints(text, inner, 0); yield new TurretCommand.DarkestPixel(); }
                case 'B' -> { ints(text, inner, 0); yield new TurretCommand.Version(); }
                default -> null;
            };
            if (typed != null) {
                return new Command.Turret(id, typed);
            }
        }
        return new Command.Turret(id, new TurretCommand.Raw(body));
    }

    /**
     * Parse a reply line and check it answers {@code command}.
     *
     * @param command the command that was sent
     * @param line the reply, with or without CR LF
     * @return the reply's values
     * @throws ProtocolException {@link Kind#COMMAND_NOT_FOUND} or {@link Kind#ROBOT_ERROR} when the
     *     robot refused the command, {@link Kind#WRONG_REPLY} when the line answers something else
     *     (resynchronise and read on), {@link Kind#MALFORMED} when the values are wrong
     */
    public static Reply parseReply(Command command, String line) {
        String text = stripEnd(line);
        String sent = command.encode();
        if (text.strip().equals(COMMAND_NOT_FOUND)) {
            throw new ProtocolException(Kind.COMMAND_NOT_FOUND, text, "the robot does not know command '" + sent
                    + "' (it answered '" + COMMAND_NOT_FOUND
                    + "'); is a turret fitted, and is the robot in protocol mode?");
        }
        if (text.equals("z") || text.startsWith("z,")) {
            throw new ProtocolException(Kind.ROBOT_ERROR, text, "the robot refused command '" + sent
                    + "': it answered '" + text + "'; check the command's arguments");
        }
        String head = command.replyHead();
        if (!text.equals(head) && !text.startsWith(head + ",")) {
            throw new ProtocolException(Kind.WRONG_REPLY, text, "'" + text + "' does not answer command '" + sent
                    + "': its reply starts '" + head + "'");
        }
        List<String> values = text.length() == head.length() ? List.of()
                : new ArrayList<>(Arrays.asList(text.substring(head.length() + 1).split(",", -1)));
        int expected = command.replyValueCount();
        if (expected >= 0 && values.size() != expected) {
            throw new ProtocolException(Kind.MALFORMED, text, "reply '" + text + "' to command '" + sent + "' has "
                    + values.size() + " values after '" + head + "'; expected " + expected);
        }
        for (String v : values) {
            if (command.integerReply() ? !isInteger(v) : v.isEmpty() || !printable(v)) {
                throw new ProtocolException(Kind.MALFORMED, text, "reply '" + text + "' to command '" + sent
                        + "' has '" + v + "' where "
                        + (command.integerReply() ? "an integer" : "a value") + " belongs");
            }
        }
        return new Reply(command, values);
    }

    /**
     * @param e why a command line was refused by {@link #parseCommand}
     * @return the line a robot answers it with: {@link #COMMAND_NOT_FOUND} or {@link #PROTOCOL_ERROR}
     */
    public static String errorReply(ProtocolException e) {
        return e.kind() == Kind.UNKNOWN_COMMAND ? COMMAND_NOT_FOUND : PROTOCOL_ERROR;
    }

    /** @param line a line @return it without trailing CR and LF characters */
    public static String stripEnd(String line) {
        int end = line.length();
        while (end > 0 && (line.charAt(end - 1) == '\r' || line.charAt(end - 1) == '\n')) {
            end--;
        }
        return line.substring(0, end);
    }

    /** @return true when every character is printable ASCII (no control characters, no line breaks) */
    private static boolean printable(String s) {
        for (int i = 0; i < s.length(); i++) {
            if (s.charAt(i) < 0x20 || s.charAt(i) > 0x7E) {
                return false;
            }
        }
        return true;
    }

    private static boolean isInteger(String s) {
        int start = s.startsWith("-") || s.startsWith("+") ? 1 : 0;
        if (s.length() == start || s.length() - start > 10) {
            return false;
        }
        for (int i = start; i < s.length(); i++) {
            if (s.charAt(i) < '0' || s.charAt(i) > '9') {
                return false;
            }
        }
        try {
            Integer.parseInt(s);
            return true;
        } catch (NumberFormatException e) {
            return false;
        }
    }

    private static int integer(String text, String field) {
        if (!isInteger(field)) {
            throw new ProtocolException(Kind.BAD_ARGUMENTS, text, "'" + text + "': '" + field + "' is not an integer");
        }
        return Integer.parseInt(field);
    }

    /** The integers after the letter in {@code parts}, exactly {@code count} of them. */
    private static int[] ints(String text, String[] parts, int count) {
        if (parts.length - 1 != count) {
            throw new ProtocolException(Kind.BAD_ARGUMENTS, text, "'" + text + "': command " + parts[0] + " takes "
                    + count + " argument" + (count == 1 ? "" : "s") + ", not " + (parts.length - 1));
        }
        int[] v = new int[count];
        for (int i = 0; i < count; i++) {
            v[i] = integer(text, parts[i + 1]);
        }
        return v;
    }
}
