package org.kheperasim.link.io;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;

/** A TCP connection to something that speaks the Khepera protocol: the simulator's server, or a serial relay. */
public final class TcpLink extends ByteLink {
    private static final System.Logger LOG = System.getLogger(TcpLink.class.getName());

    private final Socket socket;
    private final InputStream in;
    private final OutputStream out;
    private final String address;

    private TcpLink(Socket socket, String address, LineEnd end) throws IOException {
        super(end);
        this.socket = socket;
        this.in = socket.getInputStream();
        this.out = socket.getOutputStream();
        this.address = address;
    }

    /**
     * @param host host name or address
     * @param port TCP port
     * @param end what ends each command sent
     * @param connectTimeoutMillis how long to try to connect, ms
     * @return the connected link
     * @throws IOException naming the address and the fix when nothing answers there
     */
    public static TcpLink connect(String host, int port, LineEnd end, int connectTimeoutMillis) throws IOException {
        Socket s = new Socket();
        try {
            s.connect(new InetSocketAddress(host, port), connectTimeoutMillis);
            s.setTcpNoDelay(true);
            return new TcpLink(s, host + ":" + port, end);
        } catch (IOException e) {
            s.close();
            throw new IOException("cannot connect to " + host + ":" + port + ": " + e.getMessage()
                    + "; is the simulator's protocol server or the relay running there?", e);
        }
    }

    /** @param socket a connected socket @param end line end @return a link over it */
    public static TcpLink over(Socket socket, LineEnd end) throws IOException {
        return new TcpLink(socket, String.valueOf(socket.getRemoteSocketAddress()), end);
    }

    @Override
    protected int readSome(byte[] into, int timeoutMillis) throws IOException {
        socket.setSoTimeout(Math.max(1, timeoutMillis));
        try {
            int n = in.read(into);
            if (n < 0) {
                throw new LinkClosedException("the connection to " + address + " was closed by the far end");
            }
            return n;
        } catch (SocketTimeoutException e) {
            return 0;
        } catch (LinkClosedException e) {
            throw e;
        } catch (IOException e) {
            throw new LinkClosedException("the connection to " + address + " broke: " + e.getMessage());
        }
    }

    @Override
    protected int available() throws IOException {
        return in.available();
    }

    @Override
    protected void writeBytes(byte[] bytes) throws IOException {
        try {
            out.write(bytes);
            out.flush();
        } catch (IOException e) {
            throw new LinkClosedException("the connection to " + address + " broke: " + e.getMessage());
        }
    }

    @Override
    public String describe() {
        return "tcp://" + address;
    }

    @Override
    public void close() {
        try {
            socket.close();
        } catch (IOException e) {
            // Nothing left to do with a socket that will not close; worth a note when tracking down a leak.
            LOG.log(System.Logger.Level.DEBUG, "closing " + describe() + " failed: " + e);
        }
    }
}
