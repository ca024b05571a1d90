package org.kheperasim.sim.commandlog;

/** A command log that stops before its end line: the run that wrote it did not finish it. */
public final class TornLogException extends LogFormatException {
    private static final long serialVersionUID = 1L;

    /**
     * @param line the last line read, from 1
     * @param what what was found
     */
    public TornLogException(long line, String what) {
        super(line, what);
    }
}
