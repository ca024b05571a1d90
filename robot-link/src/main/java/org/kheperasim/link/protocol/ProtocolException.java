package org.kheperasim.link.protocol;

/**
 * A line does not follow the protocol. The message names the line, what was expected and, for a
 * reply, the command it answers.
 */
public class ProtocolException extends RuntimeException {
    /** What kind of mistake the line makes. */
    public enum Kind {
        /** The robot answered {@code Command not found}: it does not know the command letter. */
        COMMAND_NOT_FOUND,
        /** The robot answered {@code z,...}: it knows the letter but not the arguments. */
        ROBOT_ERROR,
        /** A reply starts with another letter than the command's (a stale reply, a banner, noise). */
        WRONG_REPLY,
        /** A line has the right letter but the wrong number or form of values. */
        MALFORMED,
        /** A command line names no known command (a server answers {@code Command not found}). */
        UNKNOWN_COMMAND,
        /** A command line has a known letter but bad arguments (a server answers {@code z,Protocol error}). */
        BAD_ARGUMENTS
    }

    private final Kind kind;
    private final String line;

    /**
     * @param kind what is wrong
     * @param line the offending line, without its terminator
     * @param message the whole explanation
     */
    public ProtocolException(Kind kind, String line, String message) {
        super(message);
        this.kind = kind;
        this.line = line;
    }

    /** @return what is wrong */
    public Kind kind() {
        return kind;
    }

    /** @return the offending line, without its terminator */
    public String line() {
        return line;
    }
}
