package org.kheperasim.link.io;

import java.io.IOException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/** Two link ends joined in memory, for tests: what one writes, the other reads. */
public final class MemoryLink extends ByteLink {

    /** One direction: a byte queue that can be closed. */
    static final class Pipe {
        private final ReentrantLock lock = new ReentrantLock();
        private final Condition data = lock.newCondition();
        private byte[] buf = new byte[256];
        private int size;
        private boolean closed;

        void write(byte[] bytes) throws LinkClosedException {
            lock.lock();
            try {
                if (closed) {
                    throw new LinkClosedException("the memory link was closed");
                }
                if (size + bytes.length > buf.length) {
                    buf = java.util.Arrays.copyOf(buf, Math.max(buf.length * 2, size + bytes.length));
                }
                System.arraycopy(bytes, 0, buf, size, bytes.length);
                size += bytes.length;
                data.signalAll();
            } finally {
                lock.unlock();
            }
        }

        int read(byte[] into, long timeoutMillis) throws IOException {
            lock.lock();
            try {
                long nanos = TimeUnit.MILLISECONDS.toNanos(timeoutMillis);
                while (size == 0 && !closed && nanos > 0) {
                    nanos = data.awaitNanos(nanos);
                }
                if (size == 0) {
                    if (closed) {
                        throw new LinkClosedException("the memory link was closed by the far end");
                    }
                    return 0;
                }
                int n = Math.min(size, into.length);
                System.arraycopy(buf, 0, into, 0, n);
                System.arraycopy(buf, n, buf, 0, size - n);
                size -= n;
                return n;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new java.io.InterruptedIOException("interrupted while reading the memory link");
            } finally {
                lock.unlock();
            }
        }

        int available() {
            lock.lock();
            try {
                return size;
            } finally {
                lock.unlock();
            }
        }

        void close() {
            lock.lock();
            try {
                closed = true;
                data.signalAll();
            } finally {
                lock.unlock();
            }
        }
    }

    private final Pipe in;
    private final Pipe out;
    private final String name;

    private MemoryLink(Pipe in, Pipe out, String name, LineEnd end) {
        super(end);
        this.in = in;
        this.out = out;
        this.name = name;
    }

    /**
     * @param hostEnd what ends the host's lines (commands)
     * @param robotEnd what ends the robot's lines (replies)
     * @return the two ends: [0] the host's, [1] the robot's
     */
    public static MemoryLink[] pair(LineEnd hostEnd, LineEnd robotEnd) {
        Pipe toRobot = new Pipe();
        Pipe toHost = new Pipe();
        return new MemoryLink[] {new MemoryLink(toHost, toRobot, "memory (host end)", hostEnd),
                new MemoryLink(toRobot, toHost, "memory (robot end)", robotEnd)};
    }

    @Override
    protected int readSome(byte[] into, int timeoutMillis) throws IOException {
        return in.read(into, timeoutMillis);
    }

    @Override
    protected int available() {
        return in.available();
    }

    @Override
    protected void writeBytes(byte[] bytes) throws IOException {
        out.write(bytes);
    }

    /**
     * Write raw characters with no terminator (tests: noise, half lines).
     *
     * @param text the characters
     * @throws IOException when the link is closed
     */
    public void writeRaw(String text) throws IOException {
        out.write(text.getBytes(java.nio.charset.StandardCharsets.ISO_8859_1));
    }

    @Override
    public String describe() {
        return name;
    }

    @Override
    public void close() {
        in.close();
        out.close();
    }
}
