package org.kheperasim.link.protocol.dialect;

import java.util.List;
import java.util.Locale;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.EpuckCommand;
import org.kheperasim.link.protocol.KheperaProtocol;
import org.kheperasim.link.protocol.ProtocolException;
import org.kheperasim.link.protocol.ProtocolException.Kind;
import org.kheperasim.link.protocol.Reply;

/**
 * The e-puck's ASCII protocol, as GCtronic's SerCom firmware answers it (its {@code asercom} command
 * loop, SerCom 1.1.3 of 2006 and the e-puck2's asercom2 of 2018; GCtronic's e-puck documentation):
 * the letters a controller needs, {@code D} speeds (steps/s, ±1000), {@code E} read speeds,
 * {@code L} LEDs (0..7, 8 = all; actions 0 off, 1 on, 2 inverse), {@code N} proximity (8 values),
 * {@code O} ambient light (8), {@code P} set and {@code Q} read the step counters, {@code B} body LED,
 * {@code F} front LED, {@code H} help, {@code S} stop, {@code R} reset, {@code V} version.
 *
 * <p>As on the robot: the command letter may be lower case; a read command's extra arguments are
 * ignored; every reply ends in CR LF; a letter the robot does not know is answered
 * {@code z,Command not found}. The firmware reads arguments with {@code sscanf} and never refuses
 * them, so a known letter with arguments it cannot use gets the command's acknowledgement and does
 * nothing here.
 */
public final class EpuckDialect implements Dialect {
    /** The e-puck. */
    public static final EpuckDialect EPUCK = new EpuckDialect();
    /** What the e-puck answers a letter it does not know. */
    public static final String COMMAND_NOT_FOUND = "z,Command not found";
    /** The version {@code V} answers (SerCom's, the e-puck1 firmware). */
    public static final String VERSION = "Version 1.1.3 September 2006";
    /** The start-up banner, after power-up or {@code R} (the firmware's, in substance). */
    public static final String BANNER = "\f\007WELCOME to the SerCom protocol on e-Puck\r\n"
            + "the EPFL education robot type \"H\" for help\r\n";

    private EpuckDialect() {
    }

    @Override public String name() { return "epuck"; }
    @Override public String robot() { return "e-puck"; }
    @Override public List<Integer> bauds() { return List.of(115200); }
    @Override public int defaultBaud() { return 115200; }
    @Override public String letters() { return "BDEFHLNOPQRSV"; }

    @Override
    public Command parseCommand(String line) {
        String text = KheperaProtocol.stripEnd(line);
        String[] parts = text.split(",", -1);
        if (parts[0].length() != 1 || !Character.isLetter(parts[0].charAt(0)) || parts[0].charAt(0) > 'z') {
            throw new ProtocolException(Kind.UNKNOWN_COMMAND, text, "'" + text + "' is not an e-puck command: a command"
                    + " is a letter and comma-separated integers, e.g. D,200,200");
        }
        char letter = Character.toUpperCase(parts[0].charAt(0));
        try {
            return switch (letter) {
                case 'B' -> new EpuckCommand.BodyLed(ints(text, parts, 1)[0]);
                case 'D' -> { int[] a = ints(text, parts, 2); yield new EpuckCommand.SetSpeed(a[0], a[1]); }
                case 'E' -> new Command.ReadSpeed();
                case 'F' -> new EpuckCommand.FrontLed(ints(text, parts, 1)[0]);
                case 'H' -> new EpuckCommand.Help();
                case 'L' -> { int[] a = ints(text, parts, 2); yield new EpuckCommand.SetLed(a[0], a[1]); }
                case 'N' -> new Command.ReadProximity();
                case 'O' -> new Command.ReadLight();
                case 'P' -> { int[] a = ints(text, parts, 2); yield new EpuckCommand.SetSteps(a[0], a[1]); }
                case 'Q' -> new EpuckCommand.ReadSteps();
                case 'R' -> new EpuckCommand.Reset();
                case 'S' -> new EpuckCommand.Stop();
                case 'V' -> new EpuckCommand.Version();
                default -> throw new ProtocolException(Kind.UNKNOWN_COMMAND, text,
                        "'" + text + "': the e-puck has no command " + letter + " here (it knows " + letters() + ")");
            };
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(Kind.BAD_ARGUMENTS, text, "'" + text + "': " + e.getMessage());
        }
    }

    /** The known letter's acknowledgement for bad arguments (the firmware never refuses them); else not found. */
    @Override
    public String errorReply(ProtocolException e) {
        if (e.kind() == Kind.BAD_ARGUMENTS && !e.line().isEmpty()) {
            return String.valueOf(Character.toLowerCase(e.line().charAt(0)));
        }
        return COMMAND_NOT_FOUND;
    }

    @Override public String overlongReply() { return COMMAND_NOT_FOUND; }

    @Override
    public Reply parseReply(Command command, String line) {
        String text = KheperaProtocol.stripEnd(line);
        if (text.strip().equals(COMMAND_NOT_FOUND)) {
            throw new ProtocolException(Kind.COMMAND_NOT_FOUND, text, "the e-puck does not know command '"
                    + command.encode() + "' (it answered '" + COMMAND_NOT_FOUND + "'); is it running the SerCom"
                    + " firmware (selector position of the ASCII protocol)?");
        }
        return KheperaProtocol.parseReply(command, text);
    }

    @Override
    public boolean looksLikeBanner(String line) {
        return line.contains("WELCOME to the SerCom") || line.contains("EPFL education robot");
    }

    @Override public int maxSpeed() { return EpuckCommand.MAX_SPEED; }
    @Override public Command setSpeeds(int left, int right) { return new EpuckCommand.SetSpeed(left, right); }
    @Override public Command readSpeeds() { return new Command.ReadSpeed(); }
    @Override public Command readProximity() { return new Command.ReadProximity(); }
    @Override public Command readLight() { return new Command.ReadLight(); }
    @Override public Command readCounters() { return new EpuckCommand.ReadSteps(); }
    @Override public Command setCounters(int left, int right) { return new EpuckCommand.SetSteps(left, right); }
    @Override public Command version() { return new EpuckCommand.Version(); }
    @Override public boolean turrets() { return false; }

    /** Exactly {@code count} integers after the letter (a read command takes none and ignores any). */
    private static int[] ints(String text, String[] parts, int count) {
        if (parts.length - 1 != count) {
            throw new ProtocolException(Kind.BAD_ARGUMENTS, text, String.format(Locale.ROOT,
                    "'%s': command %s takes %d argument%s, not %d", text, parts[0], count, count == 1 ? "" : "s",
                    parts.length - 1));
        }
        int[] v = new int[count];
        for (int i = 0; i < count; i++) {
            try {
                v[i] = Integer.parseInt(parts[i + 1].strip());
            } catch (NumberFormatException e) {
                throw new ProtocolException(Kind.BAD_ARGUMENTS, text, "'" + text + "': '" + parts[i + 1]
                        + "' is not an integer");
            }
        }
        return v;
    }

    @Override
    public String toString() {
        return name();
    }
}
