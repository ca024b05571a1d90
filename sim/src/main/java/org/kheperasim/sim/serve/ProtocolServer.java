package org.kheperasim.sim.serve;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import org.kheperasim.link.protocol.KheperaProtocol;
import org.kheperasim.link.timing.LinkTiming;

/**
 * Serves a {@link ServedRobot} over TCP in the Khepera's own serial protocol, so that any Khepera
 * client (robot-link with {@code --port tcp://HOST:PORT}, a C program, a MATLAB toolbox through a
 * socat pseudo-terminal) drives the simulated robot.
 *
 * <ul>
 *   <li>Binds to the loopback address unless another is given: exposing a robot on a network is a
 *       choice the caller makes (the CLI's {@code --bind}) and is told about.
 *   <li>One client at a time. A second connection waits up to 0.25 s for the first to leave (so a
 *       client that closes and reconnects at once is never refused), then gets one line,
 *       {@code z,Busy: robot already has a client from HOST:PORT}, and is closed.
 *   <li>A client that sends nothing for the idle timeout (60 s unless {@link #idleTimeout} says
 *       otherwise) gets {@code z,Idle: ...} and is let go, so that no client holds the robot forever.
 *   <li>When the client goes away (end of stream, error, server closed) the wheels stop at once.
 *   <li>Each command takes effect when its characters and the robot's turnaround would have passed
 *       on the serial line at the set baud, and its reply is sent when the reply's characters would
 *       have arrived ({@link LinkTiming}), both divided by the robot's speed factor. A client so sees
 *       the real robot's timing, though the bytes travel over TCP in microseconds.
 *   <li>A line longer than {@link #MAX_LINE_CHARS} is answered with {@code z,Protocol error} and
 *       discarded up to the next CR or LF without being stored; any byte sequence gets an answer,
 *       never a crash. Empty lines (the LF of a client that ends commands with CR LF) are ignored.
 * </ul>
 *
 * <p>Threads: one accepting, one per served client (at most one at a time); refusals are written
 * by the accepting thread and closed at once.
 */
public final class ProtocolServer implements AutoCloseable {
    /** The default TCP port of {@code serve}. */
    public static final int DEFAULT_PORT = 4000;
    /** The longest command line accepted, characters without the terminator. */
    public static final int MAX_LINE_CHARS = 256;

    /** What happened on the server, for a window or a log. */
    public enum EventKind {
        /** A client was accepted and is now the robot's controller. */
        CONNECTED,
        /** A client left; the robot has stopped. */
        DISCONNECTED,
        /** A second client was turned away. */
        REFUSED,
        /** Something the operator should know (an overlong line, an I/O error). */
        NOTE
    }

    /**
     * @param kind what happened
     * @param client the client's address, {@code host:port}
     * @param text a sentence for a log
     */
    public record Event(EventKind kind, String client, String text) {
    }

    private final ServedRobot robot;
    private final ServerSocket socket;
    private final Thread acceptor;
    private final List<Consumer<Event>> listeners = new CopyOnWriteArrayList<>();
    private final AtomicLong commands = new AtomicLong();
    private final Object clientLock = new Object();
    private Socket client;
    private String clientName;
    private Thread clientThread;
    private volatile boolean closed;
    private volatile long idleTimeoutMillis = DEFAULT_IDLE_TIMEOUT_MILLIS;

    /** A client that sends nothing for this long is let go, so that it cannot hold the robot forever. */
    public static final long DEFAULT_IDLE_TIMEOUT_MILLIS = 60_000;
    /** A new client waits at most this long for the previous one's leaving to finish before it is refused. */
    private static final long HANDOVER_MILLIS = 250;
    /** At most this many new clients wait for the hand-over at once; more are refused at once. */
    private static final int MAX_WAITING = 8;
    private final java.util.concurrent.atomic.AtomicInteger waiting = new java.util.concurrent.atomic.AtomicInteger();

    private ProtocolServer(ServedRobot robot, ServerSocket socket) {
        this.robot = robot;
        this.socket = socket;
        this.acceptor = new Thread(this::acceptLoop, "protocol-server-accept-" + socket.getLocalPort());
        this.acceptor.setDaemon(true);
    }

    /**
     * Start serving on the loopback address.
     *
     * @param robot the robot to serve; started here if it is not running yet
     * @param port TCP port, 0 for any free one (see {@link #port()})
     * @return the running server
     * @throws IOException when the port cannot be bound
     */
    public static ProtocolServer start(ServedRobot robot, int port) throws IOException {
        return start(robot, InetAddress.getLoopbackAddress(), port);
    }

    /**
     * Start serving.
     *
     * @param robot the robot to serve; started here if it is not running yet
     * @param bind the address to listen on: loopback keeps the robot on this computer; any other
     *     address lets other computers drive it ({@link #isExposed()})
     * @param port TCP port, 0 for any free one
     * @return the running server
     * @throws IOException when the address or port cannot be bound (the message names them)
     */
    public static ProtocolServer start(ServedRobot robot, InetAddress bind, int port) throws IOException {
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port " + port + " must lie in 0..65535 (0 = any free port)");
        }
        ServerSocket s = new ServerSocket();
        try {
            s.setReuseAddress(true);
            s.bind(new InetSocketAddress(bind, port), 128);
        } catch (IOException e) {
            s.close();
            throw new IOException("cannot listen on " + bind.getHostAddress() + ":" + port + ": " + e.getMessage()
                    + (port != 0 ? " (is another server using the port? try --port 0 for a free one)" : ""), e);
        }
        try {
            robot.start();
        } catch (IllegalStateException alreadyRunning) {
            // Started by the caller: fine.
        }
        ProtocolServer server = new ProtocolServer(robot, s);
        server.acceptor.start();
        return server;
    }

    /** @param listener told of connections, refusals and departures, on the server's threads */
    public void addListener(Consumer<Event> listener) {
        listeners.add(listener);
    }

    /** @param listener stop telling it */
    public void removeListener(Consumer<Event> listener) {
        listeners.remove(listener);
    }

    /** @return the TCP port listened on */
    public int port() {
        return socket.getLocalPort();
    }

    /** @return the address listened on */
    public InetAddress bindAddress() {
        return socket.getInetAddress();
    }

    /** @return true when other computers can connect (bound to something other than loopback) */
    public boolean isExposed() {
        return !socket.getInetAddress().isLoopbackAddress();
    }

    /**
     * @return the address a client on this computer uses, e.g. {@code tcp://127.0.0.1:4000}
     *     (robot-link's {@code --port} form)
     */
    public String url() {
        InetAddress a = socket.getInetAddress();
        String host = a.isAnyLocalAddress() ? "127.0.0.1" : a.getHostAddress();
        return "tcp://" + (host.contains(":") ? "[" + host + "]" : host) + ":" + port();
    }

    /**
     * @param millis how long a client may send nothing before it is let go (its robot stops); 0 for
     *     no limit. Applies to clients that connect from now on.
     * @return this server
     */
    public ProtocolServer idleTimeout(long millis) {
        if (millis < 0) {
            throw new IllegalArgumentException("idle timeout " + millis + " ms must not be negative (0 = none)");
        }
        this.idleTimeoutMillis = millis;
        return this;
    }

    /** @return the current client as {@code host:port}, or null when none is connected */
    public String client() {
        synchronized (clientLock) {
            return clientName;
        }
    }

    /** @return commands answered since the server started */
    public long commandsAnswered() {
        return commands.get();
    }

    /** @return the robot served */
    public ServedRobot robot() {
        return robot;
    }

    private void emit(EventKind kind, String who, String text) {
        Event e = new Event(kind, who, text);
        for (Consumer<Event> l : listeners) {
            try {
                l.accept(e);
            } catch (RuntimeException ignored) {
                // A listener's failure must not take the server down.
            }
        }
    }

    private static String name(Socket s) {
        return s.getInetAddress().getHostAddress() + ":" + s.getPort();
    }

    private void acceptLoop() {
        while (!closed) {
            Socket s;
            try {
                s = socket.accept();
            } catch (IOException e) {
                if (!closed) {
                    emit(EventKind.NOTE, "", "accept failed: " + e.getMessage());
                    LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(50));
                }
                continue;
            }
            String who = name(s);
            if (!admit(s, who, false)) {
                // Busy: the client that has it may be just leaving (it closed, and the server has
                // still to read the end of its stream and stop the robot). Let this one wait for
                // that a moment on a thread of its own, so a client that reconnects at once is
                // never refused; the acceptor goes on at once.
                if (waiting.incrementAndGet() > MAX_WAITING) {
                    waiting.decrementAndGet();
                    refuse(s, who, busyName());
                    continue;
                }
                Thread waiter = new Thread(() -> {
                    try {
                        if (!admit(s, who, true)) {
                            refuse(s, who, busyName());
                        }
                    } finally {
                        waiting.decrementAndGet();
                    }
                }, "protocol-server-waiting");
                waiter.setDaemon(true);
                waiter.start();
            }
        }
    }

    /** Make {@code s} the client if the robot is free (waiting up to the hand-over time if asked); false when busy. */
    private boolean admit(Socket s, String who, boolean wait) {
        synchronized (clientLock) {
            long deadline = System.nanoTime() + HANDOVER_MILLIS * 1_000_000L;
            while (wait && clientName != null && !closed) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    break;
                }
                try {
                    clientLock.wait(StrictMath.max(1, left / 1_000_000L));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    break;
                }
            }
            if (clientName != null || closed) {
                return false;
            }
            client = s;
            clientName = who;
            clientThread = new Thread(() -> serve(s, who), "protocol-server-client");
            clientThread.setDaemon(true);
            clientThread.start();
            return true;
        }
    }

    private String busyName() {
        synchronized (clientLock) {
            return clientName == null ? "server closing" : clientName;
        }
    }

    private void refuse(Socket s, String who, String busyWith) {
        String line = "z,Busy: robot already has a client from " + busyWith;
        try (s) {
            s.setSoTimeout(1);
            OutputStream out = s.getOutputStream();
            out.write((line + KheperaProtocol.REPLY_END).getBytes(StandardCharsets.ISO_8859_1));
            out.flush();
            s.shutdownOutput();
            // Unread input at close makes TCP reset the connection, which can lose the line: drop it.
            InputStream in = s.getInputStream();
            int n = in.available();
            if (n > 0) {
                in.skip(n);
            }
        } catch (IOException ignored) {
            // The refused client has gone already.
        }
        emit(EventKind.REFUSED, who, "refused " + who + ": the robot already has a client from " + busyWith);
    }

    private void serve(Socket s, String who) {
        emit(EventKind.CONNECTED, who, "client " + who + " connected");
        String why = "closed the connection";
        long idle = idleTimeoutMillis;
        try {
            s.setTcpNoDelay(true);
            s.setSoTimeout((int) StrictMath.min(Integer.MAX_VALUE, idle));
            new Conversation(robot, text -> emit(EventKind.NOTE, "", text), commands)
                    .handle(s.getInputStream(), s.getOutputStream());
        } catch (java.net.SocketTimeoutException e) {
            why = "sent nothing for " + idle / 1000.0 + " s and was let go (serve --idle-timeout)";
            try {
                s.getOutputStream().write(("z,Idle: no command for " + idle / 1000.0 + " s; the robot stopped and"
                        + " the connection is closed" + KheperaProtocol.REPLY_END)
                                .getBytes(StandardCharsets.ISO_8859_1));
            } catch (IOException gone) {
                // The client has gone too.
            }
        } catch (SocketException e) {
            why = closed ? "server closed" : "connection lost (" + e.getMessage() + ")";
        } catch (IOException e) {
            why = "connection lost (" + e.getMessage() + ")";
        } catch (RuntimeException e) {
            why = "server error: " + e;
        } finally {
            robot.stopWheels();
            try {
                s.close();
            } catch (IOException ignored) {
                // Closing anyway.
            }
            synchronized (clientLock) {
                if (client == s) {
                    client = null;
                    clientName = null;
                    clientThread = null;
                    clientLock.notifyAll();
                }
            }
            emit(EventKind.DISCONNECTED, who, "client " + who + " " + why + "; the robot stopped");
        }
    }

    /** Stop accepting, drop the client (its robot stops), and wait for the server's threads. */
    @Override
    public void close() {
        closed = true;
        try {
            socket.close();
        } catch (IOException ignored) {
            // Closing anyway.
        }
        Socket c;
        Thread t;
        synchronized (clientLock) {
            c = client;
            t = clientThread;
        }
        if (c != null) {
            try {
                c.close();
            } catch (IOException ignored) {
                // Closing anyway.
            }
        }
        join(acceptor);
        join(t);
    }

    private static void join(Thread t) {
        if (t == null || t == Thread.currentThread()) {
            return;
        }
        try {
            t.join(TimeUnit.SECONDS.toMillis(5));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
