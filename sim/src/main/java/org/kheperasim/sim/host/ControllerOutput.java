package org.kheperasim.sim.host;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

/**
 * What controller code gets for {@code System.out} and {@code System.err}: each line a controller's
 * thread prints goes to the run's console, stamped with its simulated time (the window shows it;
 * headless runs print it), as {@code MessagePasser} messages do; {@code System.err} lines as errors.
 * Printing costs no simulated time. Lines printed outside a run go to the real streams.
 *
 * <p>A line is at most {@link #MAX_LINE} characters: a longer one is cut into lines of that length,
 * so a controller that prints without a newline cannot fill the heap. How much a run prints in all is
 * bounded by its console (a headless run's, see {@code run.BoundedConsole}). Printing costs little real
 * time either: a whole line ({@code println} of a string, a number, an object) goes to the console as
 * it is, without being encoded to bytes and decoded again, and a line past the console's limit is only
 * counted there, so a controller that prints a hundred thousand lines a simulated second is not slowed
 * to a hang.
 */
public final class ControllerOutput {
    /** The longest line handed on, bytes; a longer one is cut. */
    static final int MAX_LINE = 8192;
    private static final PrintStream OUT = new Lines(new LineRouter(false));
    private static final PrintStream ERR = new Lines(new LineRouter(true));

    private ControllerOutput() {
    }

    /** Replaces the field {@code System.out} in controller code. */
    public static PrintStream out() {
        return OUT;
    }

    /** Replaces the field {@code System.err} in controller code. */
    public static PrintStream err() {
        return ERR;
    }

    /**
     * The stream: a {@code println} of one line hands it on whole, as the bytes it would write would make
     * it (the same text); anything else goes through the bytes.
     */
    private static final class Lines extends PrintStream {
        private final LineRouter router;

        Lines(LineRouter router) {
            super(router, true, StandardCharsets.UTF_8);
            this.router = router;
        }

        @Override
        public void println(String x) {
            if (!router.whole(x == null ? "null" : x)) {
                super.println(x);
            }
        }

        @Override
        public void println(Object x) {
            println(String.valueOf(x));
        }

        @Override
        public void println(int x) {
            println(String.valueOf(x));
        }

        @Override
        public void println(long x) {
            println(String.valueOf(x));
        }

        @Override
        public void println(double x) {
            println(String.valueOf(x));
        }

        @Override
        public void println(float x) {
            println(String.valueOf(x));
        }

        @Override
        public void println(boolean x) {
            println(String.valueOf(x));
        }

        @Override
        public void println(char x) {
            println(String.valueOf(x));
        }
    }

    /** Collects each thread's bytes up to a line end, then hands the line on. */
    private static final class LineRouter extends OutputStream {
        private final boolean error;
        private final ThreadLocal<ByteArrayOutputStream> pending = ThreadLocal.withInitial(ByteArrayOutputStream::new);
        /** Threads with part of a line pending: while there is none, a whole line needs no look at its thread's. */
        private final java.util.concurrent.atomic.AtomicInteger partial =
                new java.util.concurrent.atomic.AtomicInteger();

        LineRouter(boolean error) {
            this.error = error;
        }

        /**
         * Hand on a line printed whole, when its bytes would make it: the thread has no part of a line
         * pending, the line is short enough not to be cut and holds no line end. (A lone surrogate, which
         * UTF-8 writes as {@code ?}, stays itself: one character either way, and {@code ?} again wherever the
         * console's text is written out.)
         *
         * @return false when it must go through the bytes
         */
        boolean whole(String line) {
            int n = line.length();
            if (n * 3 >= MAX_LINE || line.indexOf('\n') >= 0 || (n > 0 && line.charAt(n - 1) == '\r')) {
                return false;
            }
            if (partial.get() > 0 && pending.get().size() > 0) {
                return false;
            }
            route(line);
            return true;
        }

        @Override
        public void write(int b) {
            ByteArrayOutputStream buffer = pending.get();
            if (b == '\n') {
                endLine(buffer);
            } else {
                append(buffer, new byte[] {(byte) b}, 0, 1);
                if (buffer.size() >= MAX_LINE) {
                    endLine(buffer);
                }
            }
        }

        @Override
        public void write(byte[] b, int off, int len) {
            ByteArrayOutputStream buffer = pending.get();
            int start = off;
            int end = off + len;
            for (int i = off; i < end; i++) {
                if (b[i] == '\n') {
                    append(buffer, b, start, i - start);
                    endLine(buffer);
                    start = i + 1;
                } else if (buffer.size() + (i - start + 1) >= MAX_LINE) {
                    append(buffer, b, start, i - start + 1);
                    endLine(buffer);
                    start = i + 1;
                }
            }
            append(buffer, b, start, end - start);
        }

        /** Add to the thread's pending line, counting the threads that have one. */
        private void append(ByteArrayOutputStream buffer, byte[] b, int off, int len) {
            if (len > 0) {
                if (buffer.size() == 0) {
                    partial.incrementAndGet();
                }
                buffer.write(b, off, len);
            }
        }

        private void endLine(ByteArrayOutputStream buffer) {
            String line = buffer.toString(StandardCharsets.UTF_8);
            if (buffer.size() > 0) {
                partial.decrementAndGet();
            }
            buffer.reset();
            if (line.endsWith("\r")) {
                line = line.substring(0, line.length() - 1);
            }
            route(line);
        }

        private void route(String line) {
            SimClock.Clock clock = SimClock.current();
            if (clock instanceof ControllerClock c) {
                c.say(error ? ConsoleLine.Kind.ERROR : ConsoleLine.Kind.MESSAGE, line);
            } else if (clock instanceof StepClock s) {
                // A step controller's print goes to the run's console too, stamped with the step's time.
                s.say(error ? ConsoleLine.Kind.ERROR : ConsoleLine.Kind.MESSAGE, line);
            } else {
                (error ? System.err : System.out).println(line);
            }
        }
    }
}
