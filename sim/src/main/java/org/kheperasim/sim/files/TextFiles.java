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
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Locale;

/**
 * Reads a text file a person wrote: UTF-8, strictly, no larger than its kind of file can be (checked
 * before it is read), and only a regular file (a pipe or a device is refused before it is opened).
 */
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
     * @throws InputFileException   (from {@code errors}) when the file is too large, not UTF-8 or not a
     *     regular file ({@link #regularSize}), or does not fit in memory
     * @throws UncheckedIOException naming the file when it cannot be read at all
     */
    public static String readUtf8(Path file, long maxBytes, String kind, ErrorFactory errors) {
        long size = checkFile(file, maxBytes, kind, errors);
        byte[] bytes;
        try (InputStream in = Files.newInputStream(file)) {
            bytes = in.readNBytes((int) Math.min(Integer.MAX_VALUE - 8, maxBytes + 1));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + kind + " " + file + ": " + e, e);
        } catch (OutOfMemoryError e) {
            throw errors.error(0, noRoom(size, kind));
        }
        if (bytes.length > maxBytes) {   // it grew since
            throw errors.error(0, tooLarge(bytes.length, maxBytes, kind));
        }
        try {
            return decode(bytes, errors);
        } catch (OutOfMemoryError e) {
            throw errors.error(0, noRoom(size, kind));
        }
    }

    /**
     * What {@link #readUtf8} checks before it opens a file: that it is a regular file ({@link #regularSize})
     * no larger than the limit.
     *
     * @param file     the file
     * @param maxBytes the largest file of this kind, bytes
     * @param kind     what the file is, for messages
     * @param errors   makes the reader's own error
     * @return its size, bytes
     * @throws InputFileException   (from {@code errors}) when it is not a regular file or too large
     * @throws UncheckedIOException naming the file when it does not exist or cannot be looked at
     */
    public static long checkFile(Path file, long maxBytes, String kind, ErrorFactory errors) {
        long size = regularSize(file, kind, errors);
        if (size > maxBytes) {
            throw errors.error(0, tooLarge(size, maxBytes, kind));
        }
        return size;
    }

    /**
     * Checks, before opening it, that a file is one that can be read whole: a regular file (a folder,
     * a pipe, a device such as {@code /dev/zero} or a terminal is refused, so that reading neither
     * hangs waiting for a writer nor runs on without end).
     *
     * @param file   the file (a symbolic link is followed)
     * @param kind   what the file is, for messages
     * @param errors makes the reader's own error
     * @return its size, bytes
     * @throws InputFileException   (from {@code errors}) when it is not a regular file
     * @throws UncheckedIOException naming the file when it does not exist or cannot be looked at
     */
    public static long regularSize(Path file, String kind, ErrorFactory errors) {
        BasicFileAttributes a;
        try {
            a = Files.readAttributes(file, BasicFileAttributes.class);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + kind + " " + file + ": " + e, e);
        }
        if (a.isDirectory()) {
            throw errors.error(0, "this is a folder; give the " + kind + " itself");
        }
        if (!a.isRegularFile()) {
            throw errors.error(0, "this is not a regular file (a pipe, a device such as /dev/zero, a socket) and is not"
                    + " read; save the " + kind + " as a file and give that");
        }
        return a.size();
    }

    private static String tooLarge(long size, long maxBytes, String kind) {
        return "the file is larger than " + size(maxBytes) + ", the limit for " + kind + "s (it has " + size(size)
                + "); is it the right file?";
    }

    private static String noRoom(long size, String kind) {
        return "the file (" + size(size) + ") does not fit in this Java's memory as a " + kind + "; give Java more with"
                + " java -Xmx4g -jar khepera-sim.jar ..., or a smaller file";
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
        return bytes >= 1 << 20 ? (bytes >> 20) + " MiB" : bytes >= 1 << 10 ? (bytes >> 10) + " KiB" : bytes + " bytes";
    }
}
