package org.kheperasim.link.session;

import org.kheperasim.link.protocol.Command;

/** A command could not be completed. The message names the command, the link and what to check. */
public class SessionException extends Exception {
    /** Why. */
    public enum Kind {
        /** No fitting reply came after every try. */
        NO_REPLY,
        /** The robot answered with an error ({@code Command not found} or {@code z,...}). */
        REFUSED,
        /** The link itself has gone (port closed, adapter unplugged, connection dropped). */
        LINK_LOST
    }

    private final Kind kind;
    private final transient Command command;

    /**
     * @param kind why
     * @param command the command that failed
     * @param message the explanation
     * @param cause the underlying failure, or null
     */
    public SessionException(Kind kind, Command command, String message, Throwable cause) {
        super(message, cause);
        this.kind = kind;
        this.command = command;
    }

    /** @return why the command failed */
    public Kind kind() {
        return kind;
    }

    /** @return the command that failed */
    public Command command() {
        return command;
    }
}
