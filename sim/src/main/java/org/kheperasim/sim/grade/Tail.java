package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

/**
 * Drains a child's output stream on a thread of its own and keeps only its last bytes, so a
 * controller that prints without end can neither block the child on a full pipe nor fill the
 * grader's memory or disk.
 */
final class Tail {
    private final byte[] ring;
    private long written;
    private final Thread thread;

    Tail(InputStream in, int keepBytes, String name) {
        this.ring = new byte[keepBytes];
        this.thread = new Thread(() -> drain(in), name);
        thread.setDaemon(true);
        thread.start();
    }

    private void drain(InputStream in) {
        byte[] buf = new byte[8192];
        try (in) {
            int n;
            while ((n = in.read(buf)) > 0) {
                synchronized (this) {
                    for (int i = 0; i < n; i++) {
                        ring[(int) (written++ % ring.length)] = buf[i];
                    }
                }
            }
        } catch (IOException e) {
            // the child is gone: what was read is what there is
        }
    }

    /**
     * @param waitMillis how long to wait for the stream's end (the child has exited)
     * @return the last bytes read, as UTF-8 text
     */
    String text(long waitMillis) {
        try {
            thread.join(waitMillis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        synchronized (this) {
            int len = (int) Math.min(written, ring.length);
            byte[] out = new byte[len];
            long start = written - len;
            for (int i = 0; i < len; i++) {
                out[i] = ring[(int) ((start + i) % ring.length)];
            }
            return new String(out, StandardCharsets.UTF_8);
        }
    }
}
