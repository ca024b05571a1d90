package org.kheperasim.link.io;

/** What ends a line written to a link: a command ends with exactly one CR or LF, a reply with CR LF. */
public enum LineEnd {
    /** Carriage return. */
    CR("\r"),
    /** Line feed, the default for commands. */
    LF("\n"),
    /** CR LF, what the robot ends its replies with. */
    CRLF("\r\n");

    private final String text;

    LineEnd(String text) {
        this.text = text;
    }

    /** @return the terminator's characters */
    public String text() {
        return text;
    }
}
