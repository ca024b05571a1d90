package org.kheperasim.sim.grade;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import org.kheperasim.sim.grade.worker.WorkerProtocol;

/**
 * A warm worker's standard error, read on a thread of its own and cut at the worker's marks
 * ({@link WorkerProtocol}) into each run's standard error, of which the last 64 KiB are kept, as a
 * child JVM's whole standard error was ({@link Tail}). What comes outside a run (the JVM's start,
 * between runs) is kept apart, as the first run's when the worker ends before it starts. A mark
 * counts only with the token of the run the grader is waiting for.
 */
final class WorkerErr {
    /** What is kept of a run's standard error, bytes. */
    static final int KEEP = 64 << 10;
    private static final byte[] MARK = WorkerProtocol.MARK.getBytes(StandardCharsets.UTF_8);
    /** A line longer than this is passed on in pieces, keeping enough of its end for a mark that straddles. */
    private static final int PIECE = KEEP;

    private final Thread thread;
    private Ring run = new Ring();
    private Ring outside = new Ring();
    private boolean inRun;
    private String token;
    private int index = -1;
    private WorkerProtocol.Mark done;
    private WorkerProtocol.Mark after;
    private boolean ended;

    WorkerErr(InputStream in, String name) {
        thread = new Thread(() -> drain(in), name);
        thread.setDaemon(true);
        thread.start();
    }

    /** The grader is about to ask for run {@code index} with this token: its marks count from now. */
    synchronized void expect(int index, String token) {
        this.index = index;
        this.token = token;
        this.run = new Ring();
        this.inRun = false;
        this.done = null;
        this.after = null;
    }

    /**
     * Wait for the run's end: its done mark, or the end of the stream (the worker has ended).
     *
     * @param millis how long at most
     * @return the done mark, or null when there was none (the worker ended, or the time ran out)
     * @throws InterruptedException if interrupted
     */
    synchronized WorkerProtocol.Mark awaitDone(long millis) throws InterruptedException {
        long end = System.nanoTime() + millis * 1_000_000L;
        while (done == null && !ended) {
            long left = (end - System.nanoTime()) / 1_000_000L;
            if (left <= 0) {
                break;
            }
            wait(left);
        }
        return done;
    }

    /**
     * Wait for what the worker says after the run: ready, or restart, or its end.
     *
     * @param millis how long at most
     * @return the mark (READY or RESTART), or null when the worker ended or the time ran out
     * @throws InterruptedException if interrupted
     */
    synchronized WorkerProtocol.Mark awaitNext(long millis) throws InterruptedException {
        long end = System.nanoTime() + millis * 1_000_000L;
        while (after == null && !ended) {
            long left = (end - System.nanoTime()) / 1_000_000L;
            if (left <= 0) {
                break;
            }
            wait(left);
        }
        return after;
    }

    /**
     * @param waitMillis how long to wait for the stream's end when the worker has ended
     * @param withStart  true to put before it what the worker printed outside its runs (the JVM's start): for
     *                   a first run that never started
     * @return the run's standard error: its last {@link #KEEP} bytes as UTF-8 text
     */
    String runText(long waitMillis, boolean withStart) {
        if (waitMillis > 0) { // join(0) would wait for ever, and a worker that goes on never ends its stream
            try {
                thread.join(waitMillis);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        synchronized (this) {
            if (withStart && !inRun && done == null) {
                Ring both = new Ring();
                both.add(outside.bytes(), 0, outside.bytes().length);
                byte[] r = run.bytes();
                both.add(r, 0, r.length);
                return new String(both.bytes(), StandardCharsets.UTF_8);
            }
            return new String(run.bytes(), StandardCharsets.UTF_8);
        }
    }

    /** @return what the worker printed outside its runs lately */
    synchronized String outsideText() {
        return new String(outside.bytes(), StandardCharsets.UTF_8);
    }

    private void drain(InputStream in) {
        byte[] buf = new byte[8192];
        byte[] line = new byte[PIECE + MARK.length + 256];
        int len = 0;
        try (in) {
            int n;
            while ((n = in.read(buf)) > 0) {
                for (int i = 0; i < n; i++) {
                    line[len++] = buf[i];
                    if (buf[i] == '\n') {
                        line(line, len, true);
                        len = 0;
                    } else if (len == line.length) {
                        // A line without end: pass on all but what could be the start of a mark.
                        int keep = MARK.length + 200;
                        line(line, len - keep, false);
                        System.arraycopy(line, len - keep, line, 0, keep);
                        len = keep;
                    }
                }
            }
        } catch (IOException e) {
            // the worker is gone: what was read is what there is
        } finally {
            synchronized (this) {
                if (len > 0) {
                    line(line, len, false);
                }
                ended = true;
                notifyAll();
            }
        }
    }

    /** One line (or piece of a line): text for the run or outside, or a mark. */
    private synchronized void line(byte[] b, int len, boolean whole) {
        int at = whole ? indexOf(b, len) : -1;
        if (at >= 0) {
            String text = new String(b, at + MARK.length, len - at - MARK.length, StandardCharsets.UTF_8).strip();
            WorkerProtocol.Mark m = WorkerProtocol.Mark.parse(text, token);
            if (m != null) {
                text(b, at);
                mark(m);
                return;
            }
        }
        text(b, len);
    }

    private void mark(WorkerProtocol.Mark m) {
        switch (m.kind()) {
            case START -> inRun = m.index() == index;
            case DONE -> {
                if (inRun && m.index() == index) {
                    inRun = false;
                    done = m;
                }
            }
            case READY, RESTART -> {
                if (done != null) {
                    after = m;
                }
            }
            default -> {
            }
        }
        notifyAll();
    }

    private void text(byte[] b, int len) {
        (inRun ? run : outside).add(b, 0, len);
    }

    private static int indexOf(byte[] b, int len) {
        outer:
        for (int i = 0; i + MARK.length <= len; i++) {
            for (int j = 0; j < MARK.length; j++) {
                if (b[i + j] != MARK[j]) {
                    continue outer;
                }
            }
            return i;
        }
        return -1;
    }

    /** The last {@link #KEEP} bytes written to it. */
    private static final class Ring {
        private final byte[] ring = new byte[KEEP];
        private long written;

        void add(byte[] b, int off, int len) {
            for (int i = off; i < off + len; i++) {
                ring[(int) (written++ % ring.length)] = b[i];
            }
        }

        byte[] bytes() {
            int len = (int) StrictMath.min(written, ring.length);
            byte[] out = new byte[len];
            long start = written - len;
            for (int i = 0; i < len; i++) {
                out[i] = ring[(int) ((start + i) % ring.length)];
            }
            return out;
        }
    }
}
