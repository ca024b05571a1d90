package org.kheperasim.sim.replay;

import java.util.ArrayList;
import java.util.List;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.engine.view.SnapshotListener;

/**
 * Keeps every sample of a live run for the plots, one {@link RobotSeries} per robot, called on the
 * engine's thread at a fixed simulated period. Only the first {@link #MAX_ROBOTS} robots are kept
 * (a swarm's plots are of one robot at a time; about 4 MB per robot per simulated hour at 100 ms).
 */
public final class SeriesRecorder implements SnapshotListener {
    /** Robots whose samples are kept. */
    public static final int MAX_ROBOTS = 16;

    private final List<RobotSeries> series = new ArrayList<>();

    @Override
    public void onSnapshot(Snapshot snapshot) {
        List<RobotView> robots = snapshot.robots();
        int n = StrictMath.min(MAX_ROBOTS, robots.size());
        synchronized (series) {
            while (series.size() < n) {
                series.add(new RobotSeries());
            }
        }
        for (int i = 0; i < n; i++) {
            series.get(i).add(snapshot.timeSeconds(), robots.get(i));
        }
    }

    /** @param robot a robot's index @return its samples, or null when it is not kept */
    public RobotSeries series(int robot) {
        synchronized (series) {
            return robot >= 0 && robot < series.size() ? series.get(robot) : null;
        }
    }
}
