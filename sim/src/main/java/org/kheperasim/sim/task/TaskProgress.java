package org.kheperasim.sim.task;

import java.util.LinkedHashMap;
import java.util.Map;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Region;
import org.kheperasim.sim.engine.CapView;
import org.kheperasim.sim.engine.RobotView;
import org.kheperasim.sim.engine.Snapshot;
import org.kheperasim.sim.engine.SnapshotListener;

/**
 * The assignment's score as a run goes, for the window, which must not touch the engine's thread:
 * regions entered by a robot's centre and caps lying in regions, taken from the snapshots (every
 * 20 ms of simulated time in the window, so a region crossed in less than that may be missed; the
 * run's result counts every millisecond). Floor coverage is not in the snapshots: a {@code cover}
 * task shows 0 until the run's result. Called on the engine's thread; read from any.
 */
public final class TaskProgress implements SnapshotListener {
    private final Arena arena;
    private final Map<String, Double> entered = new LinkedHashMap<>();
    private Map<String, Integer> capsIn = Map.of();
    private double time;

    /** @param arena the run's arena as it started (its assignment and regions) */
    public TaskProgress(Arena arena) {
        this.arena = arena;
    }

    @Override
    public synchronized void onSnapshot(Snapshot s) {
        time = s.timeSeconds();
        for (RobotView r : s.robots()) {
            for (Region g : arena.regions()) {
                if (!entered.containsKey(g.name()) && g.contains(r.x(), r.y())) {
                    entered.put(g.name(), time);
                }
            }
        }
        Map<String, Integer> caps = new LinkedHashMap<>();
        for (Region g : arena.regions()) {
            int n = 0;
            for (CapView c : s.caps()) {
                if (!c.held() && g.contains(c.x(), c.y())) {
                    n++;
                }
            }
            caps.put(g.name(), n);
        }
        capsIn = caps;
    }

    /** @return the score so far (no parts when the arena sets no task) */
    public synchronized Score score() {
        return Score.of(arena, new RunFacts(time, entered, 0, capsIn, arena.caps().size()));
    }
}
