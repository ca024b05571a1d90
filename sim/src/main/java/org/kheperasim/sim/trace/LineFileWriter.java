package org.kheperasim.sim.trace;

import java.io.IOException;
import java.io.Writer;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

/**
 * Writes a text file that survives its process being killed: the text goes to the file under its
 * final name, in whole lines only, at least once every wall-clock second (a daemon thread does it
 * while the writer's owner is busy) and when the buffer fills, and all of it, flushed to the disk,
 * at {@link #close()}. After kill -9 the file holds every line written up to about a second before;
 * nothing has to be renamed. Each write is of whole lines, but Linux ends a write to a file early, between
 * two pages, when its process is killed, so a kill -9 that lands inside one (rare: one write in several
 * hundred milliseconds of writing) leaves the last line torn; {@code TraceReader} names it.
 *
 * <p>The file is opened like any file (a symbolic link is followed, an existing file keeps its
 * permissions and is truncated). Thread-safe: one thread writes, the flusher and a shutdown hook may
 * flush.
 */
public final class LineFileWriter extends Writer {

    /** How often buffered whole lines reach the file, ms of wall-clock time. */
    public static final long FLUSH_PERIOD_MS = 1000;
    private static final int BUFFER_CHARS = 1 << 18;
    private static final Set<LineFileWriter> OPEN = ConcurrentHashMap.newKeySet();
    private static final ScheduledExecutorService FLUSHER = Executors.newSingleThreadScheduledExecutor(r -> {
        // Inheriting no thread-local values: it lives as long as the JVM, and the thread that opens
        // the first trace may hold a run's (its controller's clock).
        Thread t = new Thread(null, r, "trace-flusher", 0, false);
        t.setDaemon(true);
        return t;
    });

    private final Path file;
    private final FileChannel channel;
    private final StringBuilder pending = new StringBuilder(BUFFER_CHARS);
    private final ScheduledFuture<?> periodic;
    private IOException failure;
    private boolean closed;

    private LineFileWriter(Path file, FileChannel channel) {
        this.file = file;
        this.channel = channel;
        OPEN.add(this);
        this.periodic = FLUSHER.scheduleWithFixedDelay(this::flushQuietly, FLUSH_PERIOD_MS, FLUSH_PERIOD_MS,
                TimeUnit.MILLISECONDS);
    }

    /**
     * @param file the file, created or truncated
     * @return a writer of whole lines to it
     * @throws IOException naming the file when it cannot be opened
     */
    public static LineFileWriter open(Path file) throws IOException {
        FileChannel ch = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                StandardOpenOption.TRUNCATE_EXISTING);
        return new LineFileWriter(file, ch);
    }

    /** Writes the whole lines buffered by every open writer to their files (e.g. from a shutdown hook). */
    public static void flushAll() {
        for (LineFileWriter w : OPEN) {
            w.flushQuietly();
        }
    }

    @Override
    public void write(char[] buf, int off, int len) throws IOException {
        synchronized (lock) {
            check();
            pending.append(buf, off, len);
            if (pending.length() >= BUFFER_CHARS) {
                writeWholeLines();
            }
        }
    }

    @Override
    public void write(String str, int off, int len) throws IOException {
        synchronized (lock) {
            check();
            pending.append(str, off, off + len);
            if (pending.length() >= BUFFER_CHARS) {
                writeWholeLines();
            }
        }
    }

    /** Writes the whole lines buffered so far to the file; a line still being written waits. */
    @Override
    public void flush() throws IOException {
        synchronized (lock) {
            check();
            writeWholeLines();
        }
    }

    /** Writes everything, flushes it to the disk and closes the file. Idempotent. */
    @Override
    public void close() throws IOException {
        synchronized (lock) {
            if (closed) {
                return;
            }
            closed = true;
            periodic.cancel(false);
            OPEN.remove(this);
            try {
                if (failure == null) {
                    writeOut(pending.length());
                    channel.force(true);
                }
            } finally {
                channel.close();
            }
            if (failure != null) {
                throw failure;
            }
        }
    }

    private void flushQuietly() {
        synchronized (lock) {
            if (closed || failure != null) {
                return;
            }
            try {
                writeWholeLines();
            } catch (IOException e) {
                failure = e;
            }
        }
    }

    private void check() throws IOException {
        if (closed) {
            throw new IOException(file + " is closed");
        }
        if (failure != null) {
            throw new IOException("cannot write " + file + ": " + failure.getMessage(), failure);
        }
    }

    private void writeWholeLines() throws IOException {
        writeOut(pending.lastIndexOf("\n") + 1);
    }

    /** Writes the first {@code chars} characters of the buffer and drops them from it. */
    private void writeOut(int chars) throws IOException {
        if (chars <= 0) {
            return;
        }
        ByteBuffer bytes = StandardCharsets.UTF_8.encode(java.nio.CharBuffer.wrap(pending, 0, chars));
        try {
            while (bytes.hasRemaining()) {
                channel.write(bytes);
            }
        } catch (IOException e) {
            failure = e;
            throw e;
        }
        pending.delete(0, chars);
    }

    /** @return the file written */
    public Path file() {
        return file;
    }
}
