package org.kheperasim.link.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;

/**
 * A {@link Link} over a byte channel: splits the input into lines and frames the output. Bytes are
 * read as ISO-8859-1, so noise on the line never fails decoding.
 */
public abstract class ByteLink implements Link {
    /** A line longer than this without a terminator is handed out as it is (noise on the line). */
    static final int MAX_LINE = 512;

    private final LineEnd end;
    private final StringBuilder pending = new StringBuilder();
    private final byte[] buffer = new byte[1024];

    /** @param end what terminates the lines this link writes */
    protected ByteLink(LineEnd end) {
        this.end = end;
    }

    /**
     * Read what has arrived, waiting up to {@code timeoutMillis} for the first byte.
     *
     * @return bytes read (at least 1), 0 when nothing came in time
     * @throws LinkClosedException when the far end is gone
     */
    protected abstract int readSome(byte[] into, int timeoutMillis) throws IOException;

    /** @return bytes that can be read now without waiting */
    protected abstract int available() throws IOException;

    /** Write all of {@code bytes} or throw. */
    protected abstract void writeBytes(byte[] bytes) throws IOException;

    @Override
    public void writeLine(String line) throws IOException {
        writeBytes((line + end.text()).getBytes(StandardCharsets.ISO_8859_1));
    }

    @Override
    public String readLine(long timeoutMillis) throws IOException {
        long deadline = System.nanoTime() + timeoutMillis * 1_000_000L;
        while (true) {
            String line = takeLine();
            if (line != null) {
                return line;
            }
            long left = (deadline - System.nanoTime()) / 1_000_000L;
            if (left <= 0) {
                return null;
            }
            int n = readSome(buffer, (int) Math.min(left, Integer.MAX_VALUE));
            if (n > 0) {
                pending.append(new String(buffer, 0, n, StandardCharsets.ISO_8859_1));
            }
        }
    }

    private String takeLine() {
        while (true) {
            int i = 0;
            while (i < pending.length() && pending.charAt(i) != '\r' && pending.charAt(i) != '\n') {
                i++;
            }
            if (i == pending.length()) {
                if (pending.length() > MAX_LINE) {
                    String noise = pending.toString();
                    pending.setLength(0);
                    return noise;
                }
                return null;
            }
            String line = pending.substring(0, i);
            pending.delete(0, i + 1);
            if (!line.isEmpty()) {
                return line;
            }
        }
    }

    @Override
    public int discardInput() throws IOException {
        int dropped = pending.length();
        pending.setLength(0);
        while (available() > 0) {
            dropped += readSome(buffer, 1);
        }
        return dropped;
    }
}
