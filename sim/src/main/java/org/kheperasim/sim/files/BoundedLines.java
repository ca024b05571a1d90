package org.kheperasim.sim.files;

import java.io.IOException;
import java.io.Reader;

/**
 * Reads a stream of text line by line, as {@link java.io.BufferedReader#readLine} does, but never a
 * line longer than a limit: a stream without line ends (a binary file, {@code /dev/zero}) is refused
 * at the limit instead of filling the memory. For inputs read as they come (standard input, a pipe),
 * which cannot be measured before they are read.
 */
public final class BoundedLines {
    private final Reader in;
    private final int maxChars;
    private final TextFiles.ErrorFactory errors;
    private final StringBuilder line = new StringBuilder();
    private int lineNumber;
    /** A \r ended the last line: a \n right after it belongs to it. */
    private boolean skipLf;

    /**
     * @param in       the text, buffered by the caller
     * @param maxChars the longest line, characters
     * @param errors   makes the reader's own error for a line too long
     */
    public BoundedLines(Reader in, int maxChars, TextFiles.ErrorFactory errors) {
        this.in = in;
        this.maxChars = maxChars;
        this.errors = errors;
    }

    /**
     * @return the next line without its end ({@code \n}, {@code \r\n} or {@code \r}), or null at the end
     * @throws IOException        when the stream cannot be read
     * @throws InputFileException (from the error factory) when a line is longer than the limit
     */
    public String next() throws IOException {
        line.setLength(0);
        lineNumber++;
        while (true) {
            int c = in.read();
            if (c == '\n' && skipLf) {
                skipLf = false;
                continue;   // the \n of a \r\n: the \r ended the line
            }
            skipLf = c == '\r';
            if (c < 0) {
                return line.length() == 0 ? null : line.toString();
            }
            if (c == '\n' || c == '\r') {
                return line.toString();
            }
            if (line.length() >= maxChars) {
                throw errors.error(lineNumber,
                        "the line is longer than " + maxChars + " characters; is it the right file?");
            }
            line.append((char) c);
        }
    }
}
