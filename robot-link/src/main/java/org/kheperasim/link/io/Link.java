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

    /**
     * Run {@code hook} when the JVM exits (Ctrl-C, a kill), while this link can still carry a last
     * command. Serial ports need this: jSerialComm shuts its ports down at exit, and runs the hooks
     * given to it first.
     *
     * @param hook an unstarted thread; it must do nothing when its work was already done
     */
    default void addExitHook(Thread hook) {
        Runtime.getRuntime().addShutdownHook(hook);
    }

    /**
     * Withdraw an exit hook where the link allows it (a serial port's stays registered, so it must
     * be harmless to run twice).
     *
     * @param hook a hook given to {@link #addExitHook}
     */
    default void removeExitHook(Thread hook) {
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException e) {
            // the JVM is already exiting: the hook is running or has run
        }
    }

    /** @return what this link is connected to, for messages (e.g. {@code /dev/ttyUSB0 at 38400 baud}) */
    String describe();

    /** Close the link; closing twice does nothing. */
    @Override
    void close();
}
