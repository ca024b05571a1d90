package org.kheperasim.link.protocol.dialect;

import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import org.kheperasim.link.protocol.Command;
import org.kheperasim.link.protocol.ProtocolException;
import org.kheperasim.link.protocol.Reply;

/**
 * One robot's serial protocol: which command letters it knows, their arities and value counts,
 * its reply letters, line ends and error replies, and its baud rates. A client asks the dialect for
 * the commands a controller needs ({@link #setSpeeds}, {@link #readCounters}, ...) and checks replies
 * with {@link #parseReply}; a server (the simulator answering like the robot) reads command lines
 * with {@link #parseCommand} and answers refused ones with {@link #errorReply}.
 *
 * <p>A dialect never converts units: values are the robot's counts (Khepera speed units, e-puck
 * steps/s); what a count means belongs to the robot's type.
 *
 * <p>The dialects are {@code khepera1} (the default), {@code khepera2} and {@code epuck}; {@link
 * #named} finds one. Their commands and sources are in docs/protocol-server.md, "Dialects".
 */
public interface Dialect {

    /** The name of the default dialect, the Khepera I's. */
    String DEFAULT = "khepera1";

    /** @return the dialect's name, e.g. {@code epuck}: what {@code --dialect} and a robot type give */
    String name();

    /** @return the robot that speaks it, for messages, e.g. {@code e-puck} */
    String robot();

    /** @return the baud rates the robot's serial line offers, lowest first */
    List<Integer> bauds();

    /** @return the baud a client uses when none is given */
    int defaultBaud();

    /** @return what ends every reply line the robot sends */
    default String replyEnd() {
        return "\r\n";
    }

    /** @return the command letters the robot answers, in alphabetical order */
    String letters();

    /**
     * Parse a command line as the robot receives it.
     *
     * @param line one command, with or without its terminator
     * @return the typed command
     * @throws ProtocolException {@link ProtocolException.Kind#UNKNOWN_COMMAND} for a letter the robot
     *     does not know, {@link ProtocolException.Kind#BAD_ARGUMENTS} for a known one with wrong arguments
     */
    Command parseCommand(String line);

    /**
     * @param e why {@link #parseCommand} refused a line
     * @return the line the robot answers it with, without the line end
     */
    String errorReply(ProtocolException e);

    /** @return what the robot answers a command line too long for its buffer with */
    String overlongReply();

    /**
     * Parse a reply line and check it answers {@code command}.
     *
     * @param command the command sent
     * @param line the reply, with or without its line end
     * @return the reply's values
     * @throws ProtocolException {@link ProtocolException.Kind#COMMAND_NOT_FOUND} when the robot does
     *     not know the command, {@link ProtocolException.Kind#ROBOT_ERROR} when it refused it, {@link
     *     ProtocolException.Kind#WRONG_REPLY} for a line that answers something else
     */
    Reply parseReply(Command command, String line);

    /**
     * @param line a line received outside any reply
     * @return true when it is the robot's start-up banner (it has been reset)
     */
    boolean looksLikeBanner(String line);

    /** @return the fastest wheel speed {@link #setSpeeds} takes, in the robot's counts */
    int maxSpeed();

    /** @param left left wheel, counts @param right right wheel, counts @return the command setting both speeds */
    Command setSpeeds(int left, int right);

    /** @return the command that reads the wheel speeds */
    Command readSpeeds();

    /** @return the command that reads the eight proximity values */
    Command readProximity();

    /** @return the command that reads the eight ambient-light values */
    Command readLight();

    /** @return the command that reads the two wheel position (step) counters */
    Command readCounters();

    /** @param left left counter @param right right counter @return the command that sets both counters */
    Command setCounters(int left, int right);

    /** @return the command a client opens the conversation with (its reply names the firmware) */
    Command version();

    /** @return true when the robot takes turret commands ({@code T,id,...}: gripper, K213 vision) */
    boolean turrets();

    /** @return every dialect, the default first */
    static List<Dialect> all() {
        return List.of(KheperaDialect.KHEPERA1, KheperaDialect.KHEPERA2, EpuckDialect.EPUCK);
    }

    /**
     * @param name a dialect's name, any case, e.g. {@code epuck}
     * @return that dialect
     * @throws IllegalArgumentException naming the name and the known ones
     */
    static Dialect named(String name) {
        for (Dialect d : all()) {
            if (d.name().equals(name == null ? null : name.strip().toLowerCase(Locale.ROOT))) {
                return d;
            }
        }
        throw new IllegalArgumentException("dialect '" + name + "' is not known; give one of "
                + all().stream().map(Dialect::name).collect(Collectors.joining(", ")));
    }
}
