package org.kheperasim.link.robot;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.function.LongSupplier;
import org.kheperasim.link.session.Session;

/**
 * Writes a run to a text file ({@code # khepera-link recording v2}): a header, then one line a poll
 * cycle's sample ({@code t_s prox0..7 light0..7 posL posR speedL speedR}) and, in time order with
 * them, every line sent to the robot ({@code > t_s D,6,6}) and received from it ({@code < t_s d}).
 * Times are seconds from the run's start, the samples' zero.
 */
public final class Recorder implements Consumer<Sample>, Session.Transcript, AutoCloseable {
    private final BufferedWriter out;
    private final Path file;
    private final LongSupplier zero;

    /**
     * @param file where to write (replaced)
     * @param header what the run is: controller, port, baud
     * @throws IOException naming the file when it cannot be written
     */
    public Recorder(Path file, String header) throws IOException {
        this(file, header, () -> 0);
    }

    /**
     * @param file where to write (replaced)
     * @param header what the run is: controller, port, baud
     * @param zero the run's start, {@link System#nanoTime()} (0 until it starts: lines before are not kept)
     * @throws IOException naming the file when it cannot be written
     */
    public Recorder(Path file, String header, LongSupplier zero) throws IOException {
        this.file = file;
        this.zero = zero;
        try {
            out = Files.newBufferedWriter(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IOException("cannot write the recording " + file + ": " + e.getMessage()
                    + "; check the folder exists and is writable", e);
        }
        out.write("# khepera-link recording v2, started " + Instant.now() + "\n");
        out.write("# " + header + "\n");
        out.write("# t_s prox0..prox7 light0..light7 posL posR speedL speedR; > t_s line sent; < t_s line received\n");
    }

    @Override
    public synchronized void line(long nanos, boolean sent, String text) {
        long start = zero.getAsLong();
        if (start == 0) {
            return;
        }
        try {
            out.write(String.format(Locale.ROOT, "%c %.4f %s\n", sent ? '>' : '<', (nanos - start) / 1e9,
                    text.replace('\n', ' ').replace('\r', ' ')));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the recording " + file, e);
        }
    }

    @Override
    public synchronized void accept(Sample s) {
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, "%.4f", s.nanos() / 1e9));
        for (int v : s.proximity()) {
            b.append(' ').append(v);
        }
        for (int v : s.light()) {
            b.append(' ').append(v);
        }
        b.append(' ').append(s.leftPosition()).append(' ').append(s.rightPosition())
                .append(' ').append(s.leftSpeed()).append(' ').append(s.rightSpeed()).append('\n');
        try {
            out.write(b.toString());
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the recording " + file, e);
        }
    }

    @Override
    public synchronized void close() throws IOException {
        out.close();
    }
}
