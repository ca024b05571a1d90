package org.kheperasim.sim.commandlog;

import java.io.BufferedOutputStream;
import java.io.BufferedReader;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.Channels;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.zip.GZIPInputStream;
import java.util.zip.GZIPOutputStream;

/**
 * The channel a graded run hands its command log over: a Unix-domain socket that the grader listens
 * on, for exactly one connection, which the run's simulator makes as its first act, before any
 * controller class is loaded. Not standard output, which a controller prints to; not a file, which
 * a controller that found a way to files could rewrite. (Java cannot hand a child process a
 * descriptor beyond 0, 1 and 2, so the socket stands in for an inherited fd 3; Unix-domain sockets
 * work on Linux, macOS and Windows 10 and later alike.) The socket lives in a folder only the
 * grader's user may enter; a box shows it at {@code Box.CHANNEL} and nothing else of that folder.
 *
 * <p>The log is gzip-compressed on the way: a busy controller's turn every millisecond is a million
 * identical lines in a long run.
 */
public final class LogChannel {
    private LogChannel() {
    }

    /**
     * The run's end: connect and write.
     *
     * @param socket the grader's socket
     * @return a writer of the log (close it to end the log)
     * @throws IOException if the grader is not listening
     */
    public static Writer connect(Path socket) throws IOException {
        return open(socket).writer();
    }

    /**
     * The run's end, for a run that may have to give up its log half-way: connect, and keep the
     * socket to close it without what the writer still holds ({@link Connection#abort}).
     *
     * @param socket the grader's socket
     * @return the connection
     * @throws IOException if the grader is not listening
     */
    public static Connection open(Path socket) throws IOException {
        SocketChannel ch = SocketChannel.open(StandardProtocolFamily.UNIX);
        ch.connect(UnixDomainSocketAddress.of(socket));
        OutputStream out = new GZIPOutputStream(
                new BufferedOutputStream(Channels.newOutputStream(ch), 1 << 16), 1 << 13);
        return new Connection(ch, new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), 1 << 14));
    }

    /**
     * A run's end of the channel. A run in a JVM of its own that ends without finishing its log
     * (refused at load, out of heap) leaves on the socket only what its buffers had sent: the JVM's
     * end closes it. A run in a warm worker JVM ends the same way by {@link #abort}, so the grader
     * receives the same bytes either way.
     */
    public static final class Connection {
        private final SocketChannel channel;
        private final Writer writer;

        private Connection(SocketChannel channel, Writer writer) {
            this.channel = channel;
            this.writer = writer;
        }

        /** @return the writer of the log (close it to end the log whole) */
        public Writer writer() {
            return writer;
        }

        /** Close the socket at once, dropping what the writer and the compressor still hold, as a JVM's end would. */
        public void abort() {
            try {
                channel.close();
            } catch (IOException e) {
                // closed already
            }
        }
    }

    /**
     * @param file     a log a {@link Receiver} wrote
     * @param maxBytes the most text read from it, bytes uncompressed: a log that holds more ends in an
     *                 error there (a small compressed log can hold a great deal)
     * @return its text, uncompressed as it is read
     * @throws IOException if it cannot be opened
     */
    public static BufferedReader read(Path file, long maxBytes) throws IOException {
        InputStream in = new GZIPInputStream(Files.newInputStream(file), 1 << 13);
        InputStream bounded = new java.io.FilterInputStream(in) {
            private long read;

            @Override
            public int read() throws IOException {
                byte[] one = new byte[1];
                return read(one, 0, 1) < 0 ? -1 : one[0] & 0xff;
            }

            @Override
            public int read(byte[] b, int off, int len) throws IOException {
                int n = super.read(b, off, len);
                read += StrictMath.max(0, n);
                if (read > maxBytes) {
                    throw new IOException("the command log holds more than " + (maxBytes >> 20) + " MiB of text");
                }
                return n;
            }
        };
        return new BufferedReader(new InputStreamReader(bounded, StandardCharsets.UTF_8), 1 << 16);
    }

    /** The grader's end: listens for one run, and copies what it sends to a file, up to a limit. */
    public static final class Receiver implements AutoCloseable {
        private final ServerSocketChannel server;
        private final Path socket;
        private final Path file;
        private final long maxBytes;
        private final Thread copier;
        private volatile boolean connected;
        private volatile boolean overLimit;
        private volatile long bytes;

        /**
         * @param socket   where to listen (its folder must exist, and be the grader's own)
         * @param file     where the log goes (compressed, as sent)
         * @param maxBytes the most of it kept; a run that sends more is cut off ({@link #overLimit})
         * @throws IOException if the socket cannot be made
         */
        public Receiver(Path socket, Path file, long maxBytes) throws IOException {
            this.socket = socket;
            this.file = file;
            this.maxBytes = maxBytes;
            Files.deleteIfExists(socket);
            server = ServerSocketChannel.open(StandardProtocolFamily.UNIX);
            server.bind(UnixDomainSocketAddress.of(socket));
            try {
                // A boxed run's user (another uid, for a root grader) must be able to connect; the folder keeps others
                // out.
                Files.setPosixFilePermissions(socket, PosixFilePermissions.fromString("rw-rw-rw-"));
            } catch (UnsupportedOperationException e) {
                // not a POSIX file system (Windows): the folder's own access rules apply
            }
            copier = new Thread(this::copy, "command-log " + file.getFileName());
            copier.setDaemon(true);
            copier.start();
        }

        /** @return the socket the run connects to */
        public Path socket() {
            return socket;
        }

        /** @return the log as received (compressed) */
        public Path file() {
            return file;
        }

        private void copy() {
            try (SocketChannel ch = server.accept(); InputStream in = Channels.newInputStream(ch);
                    OutputStream out = new BufferedOutputStream(Files.newOutputStream(file), 1 << 16)) {
                connected = true;
                closeServer(); // the one connection: no one else may send a log for this run
                byte[] buf = new byte[1 << 16];
                int n;
                while ((n = in.read(buf)) > 0) {
                    if (bytes + n > maxBytes) {
                        overLimit = true;
                        return; // closing cuts the run's log off: its writes fail, and it is a torn log
                    }
                    out.write(buf, 0, n);
                    bytes += n;
                }
            } catch (IOException e) {
                // closed before a run connected, or the run went away: what was copied is what there is
            } finally {
                closeServer();
            }
        }

        /**
         * Wait until the run has closed its end (it has exited) and the log is all on disk.
         *
         * @param millis how long at most
         * @return true when the copy has ended
         */
        public boolean awaitEnd(long millis) {
            try {
                copier.join(millis);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            return !copier.isAlive();
        }

        /** @return true when the run connected */
        public boolean connected() {
            return connected;
        }

        /** @return true when the run sent more than the limit (its log was cut off) */
        public boolean overLimit() {
            return overLimit;
        }

        /** @return the log's compressed bytes received */
        public long bytes() {
            return bytes;
        }

        private void closeServer() {
            try {
                server.close();
                Files.deleteIfExists(socket);
            } catch (IOException e) {
                // already gone
            }
        }

        @Override
        public void close() {
            closeServer();
            copier.interrupt();
            awaitEnd(5000);
        }
    }
}
