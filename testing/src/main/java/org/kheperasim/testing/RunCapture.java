package org.kheperasim.testing;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.engine.view.SnapshotListener;
import org.kheperasim.sim.host.ConsoleLine;
import org.kheperasim.sim.host.ConsoleSink;

/**
 * What a live run tells a test besides its trace: each robot's collision count at every sample (a trace
 * has no such column, and the count sees bumps between samples), and the console: the controllers'
 * messages and the simulator's errors, each error with the student's line where it can be found.
 *
 * <p>It listens at the trace's own sample period, so the engine stops at no tick it would not stop at
 * anyway, and the run stays the one {@code khepera-sim run --trace} makes.
 */
final class RunCapture implements SnapshotListener, ConsoleSink {

    /**
     * An error the simulator reported about a controller.
     *
     * @param source the robot's controller name, as the console shows it ({@code Name} or {@code Name#1})
     * @param nanos simulated time, ns
     * @param text what it said
     * @param where the student's line, when found
     */
    record Error(String source, long nanos, String text, Optional<String> where) {
    }

    private long[] times = new long[256];
    private final List<int[]> counts = new ArrayList<>();
    private int samples;
    private final List<String> console = new ArrayList<>();
    private final List<Error> errors = new ArrayList<>();

    @Override
    public synchronized void onSnapshot(Snapshot s) {
        if (samples == times.length) {
            times = Arrays.copyOf(times, samples * 2);
        }
        times[samples++] = s.timeNanos();
        List<RobotView> robots = s.robots();
        int[] c = new int[robots.size()];
        for (int i = 0; i < c.length; i++) {
            c[i] = robots.get(i).collisions();
        }
        counts.add(c);
    }

    @Override
    public synchronized void accept(ConsoleLine line) {
        console.add(line.format());
        if (line.kind() == ConsoleLine.Kind.ERROR) {
            // A rule broken at run time is refused on the controller's own thread: its stack names the line.
            Optional<String> where = StudentLines.inText(line.text())
                    .or(() -> StudentLines.belowRefusal(Thread.currentThread().getStackTrace()));
            errors.add(new Error(line.source(), line.timeNanos(), line.text(), where));
        }
    }

    /**
     * @param robot the robot's index
     * @param sampleNanos the times of its trace samples, ns
     * @param n how many there are
     * @param finalCount its collision count at the end of the run
     * @return its collision count at each sample (the last sample of a trace is written at the run's end,
     *     after the listeners were last called: it gets {@code finalCount})
     */
    synchronized int[] collisionsAt(int robot, long[] sampleNanos, int n, int finalCount) {
        int[] out = new int[n];
        int j = 0;
        for (int k = 0; k < n; k++) {
            while (j < samples && times[j] < sampleNanos[k]) {
                j++;
            }
            out[k] = j < samples && times[j] == sampleNanos[k] && robot < counts.get(j).length ? counts.get(j)[robot] : -1;
        }
        if (n > 0 && out[n - 1] < 0) {
            out[n - 1] = finalCount;
        }
        return out;
    }

    /** @return the console's lines, as {@code khepera-sim run} prints them */
    synchronized List<String> console() {
        return List.copyOf(console);
    }

    /**
     * @param source a robot's controller name as the console shows it
     * @return the first error reported for it, or empty
     */
    synchronized Optional<Error> firstError(String source) {
        return errors.stream().filter(e -> e.source().equals(source)).findFirst();
    }
}
