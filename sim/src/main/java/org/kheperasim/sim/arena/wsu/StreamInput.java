package org.kheperasim.sim.arena.wsu;

/**
 * A cursor over the bytes of a Java serialization stream: big-endian numbers and modified UTF-8
 * strings, each read checked against the end of the file. Every fault is a
 * {@link WsuWorldException} naming the byte where it lies.
 */
final class StreamInput {
    private final byte[] bytes;
    private final String source;
    private int pos;

    /**
     * @param bytes  the whole file
     * @param source the file's name, for errors
     */
    StreamInput(byte[] bytes, String source) {
        this.bytes = bytes;
        this.source = source;
    }

    /** @return the offset of the next byte */
    int offset() {
        return pos;
    }

    /** @return how many bytes are left */
    int remaining() {
        return bytes.length - pos;
    }

    /** @return true when every byte has been read */
    boolean atEnd() {
        return pos >= bytes.length;
    }

    /** @return an error at {@code offset} saying {@code what} */
    WsuWorldException error(long offset, String what) {
        return new WsuWorldException(source, offset, what);
    }

    private void need(int n, String what) {
        if (n > remaining()) {
            throw error(pos, "the file ends inside " + what + " (" + n + " bytes needed, " + remaining()
                    + " left): it is truncated; save the world again in the WSU simulator, or copy the whole file");
        }
    }

    /** @param what what the byte is, for errors @return the next byte, 0..255, without consuming it */
    int peek(String what) {
        need(1, what);
        return bytes[pos] & 0xFF;
    }

    /** @return the next byte, 0..255 */
    int u1(String what) {
        need(1, what);
        return bytes[pos++] & 0xFF;
    }

    /** @return the next two bytes as an unsigned number */
    int u2(String what) {
        need(2, what);
        int v = ((bytes[pos] & 0xFF) << 8) | (bytes[pos + 1] & 0xFF);
        pos += 2;
        return v;
    }

    /** @return the next four bytes as a signed number */
    int s4(String what) {
        need(4, what);
        int v = ((bytes[pos] & 0xFF) << 24) | ((bytes[pos + 1] & 0xFF) << 16) | ((bytes[pos + 2] & 0xFF) << 8)
                | (bytes[pos + 3] & 0xFF);
        pos += 4;
        return v;
    }

    /** @return the next eight bytes as a signed number */
    long s8(String what) {
        need(8, what);
        long hi = s4(what) & 0xFFFF_FFFFL;
        long lo = s4(what) & 0xFFFF_FFFFL;
        return (hi << 32) | lo;
    }

    /** @return the next {@code n} bytes, {@code n} already checked to be non-negative */
    byte[] bytes(int n, String what) {
        need(n, what);
        byte[] out = new byte[n];
        System.arraycopy(bytes, pos, out, 0, n);
        pos += n;
        return out;
    }

    /** A string with a two-byte length, as {@code DataOutput.writeUTF} writes it. */
    String utf(String what) {
        int length = u2("the length of " + what);
        return modifiedUtf8(length, what);
    }

    /** A string with an eight-byte length ({@code TC_LONGSTRING}). */
    String longUtf(String what) {
        int at = pos;
        long length = s8("the length of " + what);
        if (length < 0 || length > remaining()) {
            throw error(at, what + " claims " + length + " bytes but " + remaining()
                    + " are left: the file is damaged or truncated");
        }
        return modifiedUtf8((int) length, what);
    }

    /** Decode {@code length} bytes of Java's modified UTF-8 (one to three bytes per character). */
    private String modifiedUtf8(int length, String what) {
        need(length, what);
        int end = pos + length;
        StringBuilder sb = new StringBuilder(length);
        while (pos < end) {
            int at = pos;
            int a = bytes[pos++] & 0xFF;
            if (a < 0x80) {
                sb.append((char) a);
            } else if ((a & 0xE0) == 0xC0) {
                int b = continuation(end, at, what);
                sb.append((char) (((a & 0x1F) << 6) | b));
            } else if ((a & 0xF0) == 0xE0) {
                int b = continuation(end, at, what);
                int c = continuation(end, at, what);
                sb.append((char) (((a & 0x0F) << 12) | (b << 6) | c));
            } else {
                throw error(at, String.format("byte 0x%02X cannot start a character in %s (modified UTF-8):"
                        + " the file is damaged", a, what));
            }
        }
        return sb.toString();
    }

    private int continuation(int end, int start, String what) {
        if (pos >= end || (bytes[pos] & 0xC0) != 0x80) {
            throw error(start, "a character in " + what + " is cut short (modified UTF-8): the file is damaged");
        }
        return bytes[pos++] & 0x3F;
    }
}
