package org.kheperasim.sim.files;

/**
 * A file (or text) that a reader refuses. The message reads {@code source:line: what is wrong and
 * the fix}, or {@code source: what is wrong} for a fault of the file as a whole (line 0), ready to
 * show a person as it is. Each reader throws its own subclass, so a caller can tell an arena from an
 * edit log, and every reader's errors carry the same position.
 */
public class InputFileException extends IllegalArgumentException {

    private static final long serialVersionUID = 1L;

    private final String source;
    private final int line;
    private final String what;

    /**
     * @param source the file's name as the user knows it
     * @param line   1-based line number of the offending line; 0 for the file as a whole
     * @param what   what is wrong and how to fix it
     */
    public InputFileException(String source, int line, String what) {
        super(line > 0 ? source + ":" + line + ": " + what : source + ": " + what);
        this.source = source;
        this.line = Math.max(0, line);
        this.what = what;
    }

    /** @return the file's name as the user knows it */
    public String source() {
        return source;
    }

    /** @return the 1-based line number of the offending line; 0 when the fault is the whole file's */
    public int line() {
        return line;
    }

    /** @return what is wrong and the fix, without the position */
    public String what() {
        return what;
    }
}
