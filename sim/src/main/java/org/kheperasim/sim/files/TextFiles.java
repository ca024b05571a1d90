package org.kheperasim.sim.files;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/** Reads a text file a person wrote: UTF-8, strictly, and no larger than its kind of file can be. */
public final class TextFiles {

    /** Makes a reader's own error for a line (0 = the whole file) and a message. */
    @FunctionalInterface
    public interface ErrorFactory {
        /**
         * @param line 1-based line, or 0 for the whole file
         * @param what what is wrong and the fix
         * @return the reader's exception
         */
        InputFileException error(int line, String what);
    }

    private TextFiles() {
    }

    /**
     * @param file     the file
     * @param maxBytes the largest file of this kind, bytes
     * @param kind     what the file is, for messages, e.g. {@code "arena file"}
     * @param errors   makes the reader's own error
     * @return the text
     * @throws InputFileException   (from {@code errors}) when the file is too large or not UTF-8
     * @throws UncheckedIOException naming the file when it cannot be read at all
     */
    public static String readUtf8(Path file, long maxBytes, String kind, ErrorFactory errors) {
        byte[] bytes;
        try (InputStream in = Files.newInputStream(file)) {
            bytes = in.readNBytes((int) Math.min(Integer.MAX_VALUE - 8, maxBytes + 1));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + kind + " " + file + ": " + e, e);
        }
        if (bytes.length > maxBytes) {
            throw errors.error(0, "the file is larger than " + size(maxBytes) + ", the limit for " + kind
                    + "s; is it the right file?");
        }
        return decode(bytes, errors);
    }

    /**
     * Decodes UTF-8 strictly.
     *
     * @param bytes  the file's bytes
     * @param errors makes the reader's own error, at the line of the first bad byte
     * @return the text
     */
    public static String decode(byte[] bytes, ErrorFactory errors) {
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CharBuffer out = CharBuffer.allocate(bytes.length);
        CoderResult r = decoder.decode(in, out, true);
        if (r.isUnderflow()) {
            r = decoder.flush(out);
        }
        if (r.isError()) {
            int at = in.position();
            int line = 1;
            int lineStart = 0;
            for (int i = 0; i < at; i++) {
                if (bytes[i] == '\n') {
                    line++;
                    lineStart = i + 1;
                }
            }
            throw errors.error(line, String.format(Locale.ROOT, "byte 0x%02X at column %d is not UTF-8 text;"
                    + " save the file as UTF-8", bytes[at] & 0xFF, at - lineStart + 1));
        }
        out.flip();
        return out.toString();
    }

    private static String size(long bytes) {
        return bytes >= 1 << 20 ? (bytes >> 20) + " MiB" : (bytes >> 10) + " KiB";
    }
}
