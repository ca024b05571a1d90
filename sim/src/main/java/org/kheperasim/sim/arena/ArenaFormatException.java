package org.kheperasim.sim.arena;

/**
 * An arena file that cannot be read. The message is {@code source:line: what is wrong and the
 * fix}, ready to show a person as it is.
 */
public final class ArenaFormatException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    private final String source;
    private final int line;

    /**
     * @param source the file's name as the user knows it
     * @param line   1-based line number of the offending line
     * @param what   what is wrong and how to fix it
     */
    public ArenaFormatException(String source, int line, String what) {
        super(source + ":" + line + ": " + what);
        this.source = source;
        this.line = line;
    }

    /** @return the file's name as the user knows it */
    public String source() {
        return source;
    }

    /** @return the 1-based line number of the offending line */
    public int line() {
        return line;
    }
}
