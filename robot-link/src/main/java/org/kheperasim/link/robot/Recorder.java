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

/** Writes every poll cycle of a run to a text file: a header, then one line a sample. */
public final class Recorder implements Consumer<Sample>, AutoCloseable {
    private final BufferedWriter out;
    private final Path file;

    /**
     * @param file where to write (replaced)
     * @param header what the run is: controller, port, baud
     * @throws IOException naming the file when it cannot be written
     */
    public Recorder(Path file, String header) throws IOException {
        this.file = file;
        try {
            out = Files.newBufferedWriter(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IOException("cannot write the recording " + file + ": " + e.getMessage()
                    + "; check the folder exists and is writable", e);
        }
        out.write("# khepera-link recording v1, started " + Instant.now() + "\n");
        out.write("# " + header + "\n");
        out.write("# t_s prox0..prox7 light0..light7 posL posR speedL speedR\n");
    }

    @Override
    public void accept(Sample s) {
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
    public void close() throws IOException {
        out.close();
    }
}
