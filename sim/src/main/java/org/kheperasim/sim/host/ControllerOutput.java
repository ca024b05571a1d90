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
 * bounded by its console (a headless run's, see {@code run.BoundedConsole}).
 */
public final class ControllerOutput {
    private static final PrintStream OUT = new PrintStream(new LineRouter(false), true, StandardCharsets.UTF_8);
    private static final PrintStream ERR = new PrintStream(new LineRouter(true), true, StandardCharsets.UTF_8);
    /** The longest line handed on, bytes; a longer one is cut. */
    static final int MAX_LINE = 8192;

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

    /** Collects each thread's bytes up to a line end, then hands the line on. */
    private static final class LineRouter extends OutputStream {
        private final boolean error;
        private final ThreadLocal<ByteArrayOutputStream> pending = ThreadLocal.withInitial(ByteArrayOutputStream::new);

        LineRouter(boolean error) {
            this.error = error;
        }

        @Override
        public void write(int b) {
            if (b == '\n') {
                endLine();
            } else {
                ByteArrayOutputStream buffer = pending.get();
                buffer.write(b);
                if (buffer.size() >= MAX_LINE) {
                    endLine();
                }
            }
        }

        @Override
        public void write(byte[] b, int off, int len) {
            for (int i = off; i < off + len; i++) {
                write(b[i]);
            }
        }

        private void endLine() {
            ByteArrayOutputStream buffer = pending.get();
            String line = buffer.toString(StandardCharsets.UTF_8);
            buffer.reset();
            if (line.endsWith("\r")) {
                line = line.substring(0, line.length() - 1);
            }
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
