package org.kheperasim.link.io;

import java.io.IOException;

/**
 * A text line link to a Khepera (or to anything answering its protocol). Lines are read up to a CR
 * or LF; empty lines are skipped, so a CR LF reply reads as one line. One thread at a time reads,
 * one writes.
 */
public interface Link extends AutoCloseable {

    /**
     * Send one line followed by this link's terminator.
     *
     * @param line the text, without terminator
     * @throws LinkClosedException when the far end or the port is gone
     * @throws IOException on another I/O failure
     */
    void writeLine(String line) throws IOException;

    /**
     * Read the next non-empty line.
     *
     * @param timeoutMillis how long to wait for a complete line, ms
     * @return the line without its terminator, or null when none was complete in time (what had
     *     arrived of it stays buffered)
     * @throws LinkClosedException when the far end or the port is gone
     * @throws IOException on another I/O failure
     */
    String readLine(long timeoutMillis) throws IOException;

    /**
     * Throw away everything received and not yet read: a boot banner, a late reply, noise.
     *
     * @return the number of characters thrown away
     * @throws IOException on an I/O failure
     */
    int discardInput() throws IOException;

    /** @return what this link is connected to, for messages (e.g. {@code /dev/ttyUSB0 at 38400 baud}) */
    String describe();

    /** Close the link; closing twice does nothing. */
    @Override
    void close();
}
