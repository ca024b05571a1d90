package org.kheperasim.sim.commandlog;

/** A command log that is torn or not in the format: names the line. */
public class LogFormatException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /**
     * @param line the line, from 1
     * @param what what is wrong with it
     */
    public LogFormatException(long line, String what) {
        super("command log line " + line + ": " + what);
    }
}
