package org.kheperasim.link.io;

import java.io.IOException;

/** Opens a link from the address a user gives: a serial port's path, or {@code tcp://host:port}. */
public final class Links {
    /** The prefix of a TCP address. */
    public static final String TCP_PREFIX = "tcp://";

    private Links() {
    }

    /**
     * @param settings the port's path (or {@code tcp://host:port}) and the serial frame (ignored for TCP)
     * @return the open link
     * @throws IOException naming the address and the fix when it cannot be opened
     */
    public static Link open(SerialSettings settings) throws IOException {
        String address = settings.path();
        if (address.startsWith(TCP_PREFIX)) {
            String hostPort = address.substring(TCP_PREFIX.length());
            int colon = hostPort.lastIndexOf(':');
            int port;
            try {
                port = Integer.parseInt(hostPort.substring(colon + 1));
            } catch (NumberFormatException | StringIndexOutOfBoundsException e) {
                port = -1;
            }
            if (colon <= 0 || port <= 0 || port > 65535) {
                throw new IOException("'" + address + "' is not a TCP address: write tcp://HOST:PORT, e.g."
                        + " tcp://localhost:4000");
            }
            return TcpLink.connect(hostPort.substring(0, colon), port, settings.lineEnd(), 5000);
        }
        return SerialLink.open(settings);
    }
}
