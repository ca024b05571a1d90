package org.kheperasim.link.protocol.dialect;

import java.util.List;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.KheperaProtocol;
import org.kheperasim.link.protocol.ProtocolException;
import org.kheperasim.link.protocol.Reply;

/**
 * The Khepera I and Khepera II protocol of Appendix A of their K-Team user manuals (Khepera User
 * Manual 5.02, 1999; Khepera2 User Manual 1.1, 2002): the 18 commands and the turret pass-through of
 * {@link KheperaProtocol}, which this dialect is exactly. The Khepera II adds the baud rates of its
 * mode jumper's positions 8 and 9 (57600 and 115200) to the Khepera I's 9600, 19200 and 38400.
 */
public final class KheperaDialect implements Dialect {
    /** The Khepera I: today's protocol. */
    public static final KheperaDialect KHEPERA1 = new KheperaDialect("khepera1", "Khepera I",
            List.of(9600, 19200, 38400));
    /** The Khepera II: the Khepera I's commands and two more baud rates. */
    public static final KheperaDialect KHEPERA2 = new KheperaDialect("khepera2", "Khepera II",
            List.of(9600, 19200, 38400, 57600, 115200));

    private final String name;
    private final String robot;
    private final List<Integer> bauds;

    private KheperaDialect(String name, String robot, List<Integer> bauds) {
        this.name = name;
        this.robot = robot;
        this.bauds = bauds;
    }

    @Override public String name() { return name; }
    @Override public String robot() { return robot; }
    @Override public List<Integer> bauds() { return bauds; }
    @Override public int defaultBaud() { return 38400; }
    @Override public String replyEnd() { return KheperaProtocol.REPLY_END; }
    @Override public String letters() { return "ABCDEFGHIJKLNOPRTW"; }
    @Override public Command parseCommand(String line) { return KheperaProtocol.parseCommand(line); }
    @Override public String errorReply(ProtocolException e) { return KheperaProtocol.errorReply(e); }
    @Override public String overlongReply() { return KheperaProtocol.PROTOCOL_ERROR; }
    @Override public Reply parseReply(Command command, String line) {
        return KheperaProtocol.parseReply(command, line);
    }

    /** The Khepera's boot banner names its BIOS and protocol versions ("Khepera BIOS version 5.02"). */
    @Override
    public boolean looksLikeBanner(String line) {
        return line.contains("BIOS") || line.startsWith("Protocol version");
    }

    @Override public int maxSpeed() { return 127; }
    @Override public Command setSpeeds(int left, int right) { return new Command.SetSpeed(left, right); }
    @Override public Command readSpeeds() { return new Command.ReadSpeed(); }
    @Override public Command readProximity() { return new Command.ReadProximity(); }
    @Override public Command readLight() { return new Command.ReadLight(); }
    @Override public Command readCounters() { return new Command.ReadPositionCounters(); }
    @Override public Command setCounters(int left, int right) { return new Command.SetPositionCounters(left, right); }
    @Override public Command version() { return new Command.ReadVersion(); }
    @Override public boolean turrets() { return true; }

    @Override
    public String toString() {
        return name;
    }
}
