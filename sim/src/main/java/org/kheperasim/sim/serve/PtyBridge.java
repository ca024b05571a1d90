package org.kheperasim.sim.serve;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * A pseudo-terminal in front of the protocol server, for clients that only open serial ports (a C
 * program, Player's Khepera driver, a MATLAB toolbox, robot-link with a path): a link at the path
 * the user chose leads to the slave of a pseudo-terminal this bridge holds ({@link PtyDevice}), and
 * each program that opens it becomes a client of the server, over TCP on this computer, as long as
 * it keeps it open.
 *
 * <p>One pseudo-terminal serves every client in turn, as a serial port does, so the path is never
 * missing nor dead between two of them. The bridge looks every 2 ms whether a program has the slave
 * open: a program that opens it and sends at once is answered in a few milliseconds (Player's driver
 * waits 0.3 s). When the program closes it, the connection closes (the robot stops) and whatever
 * either side left unread is thrown away, so nothing of one client reaches the next; a program that
 * opened, wrote and closed the port within one look is not seen, and what it wrote is thrown away
 * too. The pseudo-terminal is raw for each new client (no echo, bytes as sent), as a fresh port.
 *
 * <p>No other process is involved: the pseudo-terminal ends with this JVM, however it ends. The link
 * is removed on {@link #close()} and at exit; one left by a killed JVM (dangling) is replaced by the
 * next bridge on that path. Linux only (elsewhere {@link #start} says to connect over TCP).
 */
public final class PtyBridge implements AutoCloseable {
    /** How often the bridge looks whether a program has opened the pty, ms. */
    private static final int LOOK_MILLIS = 2;
    /**
     * How long a read of the pty waits for input while a client is there, ms (also how soon it sees the client leave).
     */
    private static final int READ_WAIT_MILLIS = 20;

    private final Path link;
    private final int port;
    private final PtyDevice pty;
    private final Consumer<String> log;
    private final Thread bridge;
    private final Thread exitHook = new Thread(this::closeQuietly, "pty-bridge-exit");
    private volatile boolean closed;
    /** The connection of the client on the pty, or null; only the bridge's thread sets it. */
    private volatile Socket connection;
    private volatile Thread replies;

    private PtyBridge(Path link, int port, PtyDevice pty, Consumer<String> log) {
        this.link = link;
        this.port = port;
        this.pty = pty;
        this.log = log;
        this.bridge = new Thread(this::bridge, "pty-bridge " + link.getFileName());
        this.bridge.setDaemon(true);
    }

    /**
     * Make the pty, put its link at {@code link} and serve each program that opens it, until {@link #close()}.
     *
     * @param link where the pty's link goes (its folder must exist; an existing file there is an
     *             error, but for a dangling link a killed bridge left)
     * @param port the server's TCP port on this computer
     * @param log  told when a program opens or closes the pty
     * @return the bridge, its link in place
     * @throws IOException when the pty or the link cannot be made, naming why
     */
    public static PtyBridge start(Path link, int port, Consumer<String> log) throws IOException {
        Path abs = link.toAbsolutePath();
        if (Files.isSymbolicLink(abs) && !Files.exists(abs)) {
            Files.delete(abs); // a link left by a bridge that was killed
        }
        if (Files.exists(abs, LinkOption.NOFOLLOW_LINKS)) {
            throw new IOException(link + " already exists; choose another --pty path or remove it");
        }
        PtyDevice pty = PtyDevice.open();
        PtyBridge b = new PtyBridge(abs, port, pty, log);
        try {
            Files.createSymbolicLink(abs, Path.of(pty.slavePath()));
        } catch (IOException | UnsupportedOperationException e) {
            pty.close();
            throw new IOException("cannot make the link " + link + " to " + pty.slavePath() + ": " + e.getMessage(), e);
        }
        Runtime.getRuntime().addShutdownHook(b.exitHook);
        b.bridge.start();
        return b;
    }

    /** @return the pty's link */
    public Path link() {
        return link;
    }

    /** @return the pty the link leads to, e.g. {@code /dev/pts/3} */
    public String device() {
        return pty.slavePath();
    }

    private void bridge() {
        byte[] buffer = new byte[4096];
        while (!closed) {
            int events = pty.poll(connection == null ? 0 : READ_WAIT_MILLIS);
            if (events < 0) {
                continue; // a failed look (a signal) says nothing: a client that is not there must not be connected
            }
            boolean present = (events & PtyDevice.POLLHUP) == 0;
            if (!present) {
                if (connection != null || (events & PtyDevice.POLLIN) != 0) {
                    // The client left (or one came and went unseen): its session ends with nothing left over.
                    leave(buffer);
                }
                pause();
                continue;
            }
            if (connection == null && !connect()) {
                pause();
                continue;
            }
            if ((events & PtyDevice.POLLIN) != 0) {
                int n = pty.read(buffer);
                if (n > 0 && !forward(buffer, n)) {
                    // The server let the connection go (it was idle, or the server closed): the next
                    // bytes the client sends open a new one.
                    drop();
                }
            }
        }
    }

    private static void pause() {
        try {
            TimeUnit.MILLISECONDS.sleep(LOOK_MILLIS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** A program has opened the pty: it becomes the server's client. */
    private boolean connect() {
        try {
            Socket s = new Socket();
            s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 2000);
            s.setTcpNoDelay(true);
            connection = s;
            replies = new Thread(() -> relayReplies(s), "pty-bridge-replies " + link.getFileName());
            replies.setDaemon(true);
            replies.start();
            log.accept("a program opened " + link + " (" + pty.slavePath() + "); it drives the robot");
            return true;
        } catch (IOException e) {
            if (!closed) {
                log.accept("a program opened " + link + ", but the server does not answer (" + e.getMessage() + ")");
            }
            return false;
        }
    }

    private boolean forward(byte[] buffer, int n) {
        try {
            OutputStream out = connection.getOutputStream();
            out.write(buffer, 0, n);
            out.flush();
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    /** What the server sends goes to the program on the pty, until the connection closes. */
    private void relayReplies(Socket s) {
        byte[] buffer = new byte[4096];
        try (InputStream in = s.getInputStream()) {
            int n;
            while ((n = in.read(buffer)) > 0) {
                pty.write(buffer, n);
            }
        } catch (IOException e) {
            // The connection or the pty closed: the session is over.
        }
    }

    /** The client closed the pty: its connection closes, and what either side left unread goes. */
    private void leave(byte[] buffer) {
        boolean had = connection != null;
        // First stop the replies (nothing more is written to the pty), then empty the pty, and only then close the
        // connection: the server sees the client go after its last replies are gone, so a client that comes once the
        // server has seen the last one go never reads what was meant for it (a reply written just before it closed).
        stopReplies();
        // Only while nobody has it open: a client that opened it meanwhile keeps its first bytes and its settings.
        // The slave is locked meanwhile (an open fails at once and is retried, as after a busy port), so that no
        // client can open it between the look that found nobody and the flush, which would throw away its first
        // command (CI once saw a client of PtyClientsTest wait in vain for its first reply).
        boolean locked = pty.lockSlave(true);
        try {
            while (pty.poll(0) == (PtyDevice.POLLIN | PtyDevice.POLLHUP) && pty.read(buffer) > 0) {
                // Bytes of a client that has gone: for nobody.
            }
            int events = pty.poll(0);
            if (events > 0 && (events & PtyDevice.POLLHUP) != 0) {
                pty.discardPending();
                pty.makeRaw();
            }
        } finally {
            if (locked) {
                pty.lockSlave(false);
            }
        }
        // A reply that came after the client closed may have gone on into the slave's own buffer, where the master's
        // flush does not reach (CI saw the next client read "d", the reply to the last one's D command). After the
        // master's flush: what was still on its way in then has arrived by now, or was thrown away by it.
        pty.discardUnreadReplies();
        drop();
        if (had) {
            log.accept("the program on " + link + " closed it; the pty is ready for the next");
        }
    }

    /** Stop relaying the server's replies, without closing the connection (the server does not see it go yet). */
    private void stopReplies() {
        Socket s = connection;
        if (s != null) {
            try {
                s.shutdownInput(); // a read blocked on it ends
            } catch (IOException ignored) {
                // Closed already: the relay ends anyway.
            }
        }
        Thread r = replies;
        if (r != null) {
            try {
                r.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** Close the connection and wait for its replies to stop, so none is written after. */
    private void drop() {
        stopReplies();
        replies = null;
        Socket s = connection;
        connection = null;
        if (s != null) {
            try {
                s.close();
            } catch (IOException ignored) {
                // Closing anyway.
            }
        }
    }

    /**
     * Close the pty (a program on it sees a hang-up), end its client's connection (the robot stops) and remove the
     * link.
     */
    @Override
    public void close() {
        closeQuietly();
        try {
            Runtime.getRuntime().removeShutdownHook(exitHook);
        } catch (IllegalStateException exiting) {
            // The JVM is exiting: the hook runs, and finds the bridge closed.
        }
    }

    private synchronized void closeQuietly() {
        if (closed) {
            return;
        }
        closed = true;
        Socket s = connection;
        if (s != null) {
            try {
                s.close();
            } catch (IOException ignored) {
                // Closing anyway.
            }
        }
        // The descriptor is closed only once no thread of the bridge can use it (its number could be reused).
        join(bridge);
        join(replies);
        pty.close();
        try {
            if (Files.isSymbolicLink(link) && Path.of(pty.slavePath()).equals(Files.readSymbolicLink(link))) {
                Files.delete(link);
            }
        } catch (IOException ignored) {
            // Nothing more to do about it.
        }
    }

    private static void join(Thread t) {
        if (t == null || t == Thread.currentThread()) {
            return;
        }
        try {
            t.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
