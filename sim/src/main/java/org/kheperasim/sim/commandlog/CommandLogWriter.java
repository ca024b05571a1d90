package org.kheperasim.sim.commandlog;

import java.io.IOException;
import java.io.Writer;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.view.DriverRecorder;

/**
 * Writes a run's command log as it goes: the header, then one line per thing the controllers did to
 * the world, in the engine's order, then the run's own result (its claim) and an end line.
 *
 * <pre>
 * khepera-commands 1
 * seed 42 / arena maze sha256=… / end-ns 600000000000 / sample-ms 250 / robots 1
 * robot 0 org.kheperasim.controllers.WallFollower WallFollower
 * settings 0 defaults
 * W 0 0            a driver's wake at the start: tick 0 (x: none, it has ended)
 * v 0 20000 5 5    speeds asked at 20000 ns: left 5, right 5
 * p 0 … 0 0        position counters set;  a 0 … 200  arm moved;  f 0 … 1  fingers closed
 * e 0              emergency stop (the controller ended, failed or was stopped)
 * q 5000000        the run was stopped early (a signal, the window's Stop): it ends at 5000000 ns
 * r 0 … 0          a read at … brought poll reply 0 (PollStep's order) in before the engine's tick did
 * i 0 …            a read at … made the vision turret take its image of that period (the trace shows it)
 * w 0 100          after a turn at tick S, the driver wakes at tick S + 100 (x: it has ended)
 * claim {…}        the run's own result, as {@code run --json} prints it
 * end 12345        the number of event lines, so a torn log is told from a whole one
 * </pre>
 *
 * A busy controller's turn every tick writes {@code w 0 1} a million times: the channel compresses
 * it (see {@link LogChannel}). A write that fails (the reader has gone) is remembered and the rest
 * dropped, never thrown into the controller that made the call: the reader sees a torn log.
 */
public final class CommandLogWriter implements DriverRecorder {
    private final Writer out;
    private final StringBuilder line = new StringBuilder(48);
    /** Events told before the header is known (commands sent in a controller's constructor); null once started. */
    private StringBuilder early = new StringBuilder();
    private long events;
    private IOException failure;

    /**
     * A log whose header comes once the run is set up ({@link #start}): what its controllers do while
     * they are made is kept until then.
     *
     * @param out where the lines go (closed by {@link #finish})
     */
    public CommandLogWriter(Writer out) {
        this.out = out;
    }

    /**
     * Write the header, then what was told before it.
     *
     * @param header what the run is
     */
    public void start(LogHeader header) {
        if (early == null) {
            throw new IllegalStateException("the command log has started already");
        }
        String before = early.toString();
        early = null;
        write(header.text());
        write(before);
    }

    @Override
    public void wake(int robot, long sliceTick, long wakeNanos) {
        line.setLength(0);
        line.append(sliceTick < 0 ? 'W' : 'w').append(' ').append(robot).append(' ');
        if (wakeNanos == Long.MAX_VALUE) {
            line.append('x');
        } else {
            // Only the wake's tick counts: the engine compares it with tick ends and divides by the tick.
            long tick = wakeNanos / Engine.TICK_NANOS;
            line.append(sliceTick < 0 ? tick : tick - sliceTick);
        }
        event();
    }

    @Override
    public void speeds(int robot, long now, int left, int right) {
        command('v', robot, now).append(' ').append(left).append(' ').append(right);
        event();
    }

    @Override
    public void positions(int robot, long now, int left, int right) {
        command('p', robot, now).append(' ').append(left).append(' ').append(right);
        event();
    }

    @Override
    public void arm(int robot, long now, int position) {
        command('a', robot, now).append(' ').append(position);
        event();
    }

    @Override
    public void fingers(int robot, long now, boolean closed) {
        command('f', robot, now).append(' ').append(closed ? 1 : 0);
        event();
    }

    @Override
    public void delivered(int robot, long now, org.kheperasim.link.timing.PollStep step) {
        command('r', robot, now).append(' ').append(step.ordinal());
        event();
    }

    @Override
    public void image(int robot, long now) {
        command('i', robot, now);
        event();
    }

    @Override
    public void stoppedAt(long nanos) {
        line.setLength(0);
        line.append("q ").append(nanos);
        event();
    }

    @Override
    public void emergencyStop(int robot) {
        line.setLength(0);
        line.append("e ").append(robot);
        event();
    }

    /**
     * Write the run's own result and the end line, and close the log.
     *
     * @param claimJson the run's result as one line of JSON
     * @throws IOException if the log could not be written whole
     */
    public void finish(String claimJson) throws IOException {
        if (early != null) {
            throw new IllegalStateException("the command log was never started");
        }
        write("claim " + claimJson.replaceAll("[\\r\\n]+", " ") + "\n");
        write("end " + events + "\n");
        try {
            out.close();
        } catch (IOException e) {
            remember(e);
        }
        if (failure != null) {
            throw failure;
        }
    }

    /** @return the number of event lines written so far */
    public long events() {
        return events;
    }

    private StringBuilder command(char kind, int robot, long now) {
        line.setLength(0);
        return line.append(kind).append(' ').append(robot).append(' ').append(now);
    }

    private void event() {
        events++;
        line.append('\n');
        write(line);
    }

    private void write(CharSequence text) {
        if (early != null) {
            early.append(text);
            return;
        }
        if (failure != null) {
            return;
        }
        try {
            out.append(text);
        } catch (IOException e) {
            remember(e);
        }
    }

    private void remember(IOException e) {
        if (failure == null) {
            failure = e;
        }
    }
}
