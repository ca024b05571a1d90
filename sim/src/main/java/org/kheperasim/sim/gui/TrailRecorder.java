package org.kheperasim.sim.gui;

import java.util.Arrays;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.engine.view.SnapshotListener;

/**
 * Keeps the path each robot took, for the trail in the arena view. Called on the engine's thread
 * at a fixed simulated period; it only appends to an array under a short lock and never waits on
 * the screen. The newest {@link #CAPACITY} points are kept.
 */
public final class TrailRecorder implements SnapshotListener {
    /** Points kept per robot. */
    public static final int CAPACITY = 20_000;

    private float[][] xs = new float[0][];
    private float[][] ys = new float[0][];
    private int[] counts = new int[0];
    private int[] starts = new int[0];

    @Override
    public synchronized void onSnapshot(Snapshot snapshot) {
        int n = snapshot.robots().size();
        if (xs.length != n) {
            xs = new float[n][CAPACITY];
            ys = new float[n][CAPACITY];
            counts = new int[n];
            starts = new int[n];
        }
        for (RobotView r : snapshot.robots()) {
            int i = r.id();
            int at = (starts[i] + counts[i]) % CAPACITY;
            xs[i][at] = (float) r.x();
            ys[i][at] = (float) r.y();
            if (counts[i] < CAPACITY) {
                counts[i]++;
            } else {
                starts[i] = (starts[i] + 1) % CAPACITY;
            }
        }
    }

    /** Forget every trail (a new run). */
    public synchronized void clear() {
        Arrays.fill(counts, 0);
        Arrays.fill(starts, 0);
    }

    /**
     * @param robot a robot's id
     * @return its trail as x0, y0, x1, y1, … mm, oldest first (a copy)
     */
    public synchronized float[] trail(int robot) {
        if (robot >= counts.length) {
            return new float[0];
        }
        float[] out = new float[counts[robot] * 2];
        for (int k = 0; k < counts[robot]; k++) {
            int at = (starts[robot] + k) % CAPACITY;
            out[2 * k] = xs[robot][at];
            out[2 * k + 1] = ys[robot][at];
        }
        return out;
    }
}
