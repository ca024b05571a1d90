package org.kheperasim.link.fake;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

/**
 * A fake robot behind a loopback TCP port: the first client that connects gets it (robot-link opens
 * {@code tcp://127.0.0.1:PORT} as it opens a serial port).
 *
 * @param <T> the fake's type
 */
public final class OnSocket<T> implements AutoCloseable {
    /** Makes a fake on a connection's streams, started. @param <T> the fake's type */
    public interface Maker<T> {
        /** @param in from the client @param out to the client @return the fake, answering */
        T make(InputStream in, OutputStream out) throws IOException;
    }

    private final ServerSocket server;
    private final CompletableFuture<T> robot = new CompletableFuture<>();
    private volatile Socket socket;

    private OnSocket(ServerSocket server) {
        this.server = server;
    }

    /** @param maker makes the fake @param <T> its type @return listening on a free port */
    public static <T> OnSocket<T> start(Maker<T> maker) throws IOException {
        OnSocket<T> s = new OnSocket<>(new ServerSocket(0));
        Thread accept = new Thread(() -> {
            try {
                s.socket = s.server.accept();
                s.robot.complete(maker.make(s.socket.getInputStream(), s.socket.getOutputStream()));
            } catch (IOException e) {
                s.robot.completeExceptionally(e);
            }
        }, "fake-robot-accept");
        accept.setDaemon(true);
        accept.start();
        return s;
    }

    /** @return the address robot-link opens */
    public String url() {
        return "tcp://127.0.0.1:" + server.getLocalPort();
    }

    /** @return the fake, once a client has connected */
    public T robot() throws Exception {
        return robot.get(10, TimeUnit.SECONDS);
    }

    @Override
    public void close() throws IOException {
        server.close();
        if (socket != null) {
            socket.close();
        }
    }
}
