package org.kheperasim.sim.serve;

import com.sun.jna.Library;
import com.sun.jna.Native;
import com.sun.jna.NativeLong;
import java.io.IOException;

/**
 * The master side of a pseudo-terminal, made through the C library (Linux): a program that opens
 * its slave path sees a serial port. Whether a program has the slave open shows as the absence of
 * a hang-up on the master, which is how {@link PtyBridge} tells clients come and go.
 *
 * <p>Not thread-safe beyond this: one thread reads and polls, another may write.
 */
final class PtyDevice implements AutoCloseable {

    /** The C library's calls this needs (pollfd passed as two ints: fd, then events | revents << 16). */
    interface LibC extends Library {
        int posix_openpt(int flags);

        int grantpt(int fd);

        int unlockpt(int fd);

        String ptsname(int fd);

        int open(String path, int flags);

        int close(int fd);

        int tcgetattr(int fd, byte[] termios);

        void cfmakeraw(byte[] termios);

        int tcsetattr(int fd, int when, byte[] termios);

        int tcflush(int fd, int queues);

        int ioctl(int fd, NativeLong request, int[] argument);

        int poll(int[] fds, NativeLong count, int timeoutMillis);

        NativeLong read(int fd, byte[] buffer, NativeLong count);

        NativeLong write(int fd, byte[] buffer, NativeLong count);
    }

    private static final int O_RDWR = 2;
    private static final int O_NOCTTY = 0400;
    private static final int TCSANOW = 0;
    /** On the master, only both queues at once also reach the bytes waiting for the slave to read. */
    private static final int TCIOFLUSH = 2;
    private static final int TCIFLUSH = 0;
    private static final int O_NONBLOCK = 04000;
    static final int POLLIN = 0x1;
    static final int POLLHUP = 0x10;
    /** ioctl TIOCSPTLCK (_IOW('T', 0x31, int)) where the ioctl numbers are the generic ones; 0 elsewhere (no lock). */
    private static final long TIOCSPTLCK = genericIoctls() ? 0x40045431L : 0;
    /** Larger than any platform's struct termios. */
    private static final int TERMIOS_BYTES = 256;

    private final LibC libc;
    private final int master;
    private final String slave;
    private volatile boolean closed;

    private PtyDevice(LibC libc, int master, String slave) {
        this.libc = libc;
        this.master = master;
        this.slave = slave;
    }

    /**
     * Make a pseudo-terminal: raw (no echo, no line editing, bytes as they are), and hung up until a
     * program opens its slave.
     *
     * @return the device
     * @throws IOException where the system cannot make one (not Linux, no /dev/ptmx), naming the fix
     */
    static PtyDevice open() throws IOException {
        if (!System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux")) {
            throw new IOException("a pseudo-terminal is made only on Linux; on this system connect over TCP (--port)");
        }
        LibC libc;
        try {
            libc = Native.load("c", LibC.class);
        } catch (UnsatisfiedLinkError | RuntimeException e) {
            throw new IOException("cannot reach the C library to make a pseudo-terminal (" + e.getMessage()
                    + "); connect over TCP (--port)", e);
        }
        int fd = libc.posix_openpt(O_RDWR | O_NOCTTY);
        if (fd < 0) {
            throw new IOException("cannot make a pseudo-terminal (posix_openpt failed: is /dev/ptmx there?)");
        }
        String slave = libc.grantpt(fd) == 0 && libc.unlockpt(fd) == 0 ? libc.ptsname(fd) : null;
        if (slave == null) {
            libc.close(fd);
            throw new IOException("cannot make a pseudo-terminal (grantpt/unlockpt/ptsname failed)");
        }
        PtyDevice d = new PtyDevice(libc, fd, slave);
        d.makeRaw();
        // A master whose slave was never opened does not show a hang-up; once opened and closed it does.
        int s = libc.open(slave, O_RDWR | O_NOCTTY);
        if (s >= 0) {
            libc.close(s);
        }
        return d;
    }

    /** @return the slave's path, e.g. {@code /dev/pts/3}: what a program opens */
    String slavePath() {
        return slave;
    }

    /** Raw mode, as a serial line carries the protocol: set again for each client, as a fresh port would be. */
    void makeRaw() {
        byte[] t = new byte[TERMIOS_BYTES];
        if (libc.tcgetattr(master, t) == 0) {
            libc.cfmakeraw(t);
            libc.tcsetattr(master, TCSANOW, t);
        }
    }

    private static boolean genericIoctls() {
        String arch = System.getProperty("os.arch", "");
        return arch.equals("amd64") || arch.equals("x86_64") || arch.equals("aarch64") || arch.equals("x86")
                || arch.equals("i386") || arch.startsWith("arm") || arch.startsWith("riscv");
    }

    /**
     * Lock or unlock the slave: while locked, a program's open of it fails (EIO) at once, so what the
     * bridge does between a look and an act (throwing away what a client left) cannot reach a client
     * that opened in between. Where the lock is not known (an unusual architecture), does nothing.
     *
     * @return whether the slave is now in the state asked
     */
    boolean lockSlave(boolean locked) {
        if (TIOCSPTLCK == 0) {
            return false;
        }
        return libc.ioctl(master, new NativeLong(TIOCSPTLCK), new int[] {locked ? 1 : 0}) == 0;
    }

    /** Throw away what waits in either direction: what a client that left wrote, and replies it never read. */
    void discardPending() {
        libc.tcflush(master, TCIOFLUSH);
    }

    /**
     * Throw away the replies that wait on the slave's side, unread: flushing from the master empties only the
     * bytes not yet taken in by the slave's line discipline, and a reply written just after its client closed is
     * taken in there at once (Linux), to be read by the next program that opens the pty. Opened and closed here,
     * unlocked: a program that opens it meanwhile has had no reply yet, so nothing of its own is thrown away.
     */
    void discardUnreadReplies() {
        int s = libc.open(slave, O_RDWR | O_NOCTTY | O_NONBLOCK);
        if (s >= 0) {
            libc.tcflush(s, TCIFLUSH);
            libc.close(s);
        }
    }

    /**
     * @param timeoutMillis how long to wait for input, ms (0: look only)
     * @return the poll events: {@link #POLLIN} input waits, {@link #POLLHUP} no program has the slave open;
     *         -1 when the look failed (interrupted by a signal): it tells nothing, look again
     */
    int poll(int timeoutMillis) {
        int[] fds = {master, POLLIN};
        int n = libc.poll(fds, new NativeLong(1), timeoutMillis);
        return n < 0 ? -1 : n == 0 ? 0 : (fds[1] >>> 16) & 0xffff;
    }

    /**
     * @param buffer where to read into
     * @return bytes read, or -1 when there is nothing to read (no program has it open)
     */
    int read(byte[] buffer) {
        return (int) libc.read(master, buffer, new NativeLong(buffer.length)).longValue();
    }

    /**
     * Write all of {@code bytes} to the program on the slave.
     *
     * @throws IOException when the pseudo-terminal is closed
     */
    void write(byte[] bytes, int length) throws IOException {
        int off = 0;
        while (off < length && !closed) {
            byte[] rest = off == 0 ? bytes : java.util.Arrays.copyOfRange(bytes, off, length);
            long n = libc.write(master, rest, new NativeLong(length - off)).longValue();
            if (n <= 0) {
                throw new IOException("the pseudo-terminal " + slave + " is closed");
            }
            off += (int) n;
        }
    }

    /** Close the master: a program on the slave sees a hang-up. Closing twice does nothing. */
    @Override
    public synchronized void close() {
        if (!closed) {
            closed = true;
            libc.close(master);
        }
    }
}
