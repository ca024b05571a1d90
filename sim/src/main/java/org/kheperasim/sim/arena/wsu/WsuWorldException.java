package org.kheperasim.sim.arena.wsu;

/**
 * A world file of the WSU Khepera Simulator that cannot be read: damaged, truncated, or not a WSU
 * world at all. The message is {@code file: byte N: what is wrong}, ready to show a person; for a
 * problem with the world as a whole it is {@code file: what is wrong}.
 */
public final class WsuWorldException extends IllegalArgumentException {

    private static final long serialVersionUID = 1L;

    private final String source;
    private final long offset;

    /**
     * @param source the file's name as the user knows it
     * @param offset 0-based byte offset of the fault in the file, or -1 for the world as a whole
     * @param what   what is wrong, and the fix where there is one
     */
    public WsuWorldException(String source, long offset, String what) {
        super(source + (offset >= 0 ? ": byte " + offset : "") + ": " + what);
        this.source = source;
        this.offset = offset;
    }

    /** @return the file's name as the user knows it */
    public String source() {
        return source;
    }

    /** @return the 0-based byte offset of the fault, or -1 when the fault is not at one place */
    public long offset() {
        return offset;
    }
}
