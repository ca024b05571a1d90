package org.kheperasim.sim.engine;

import java.util.List;

/**
 * The world at one instant, as the engine publishes it to listeners (the window, the trace
 * writer, metrics, tests). Immutable: a listener may keep it as long as it likes.
 *
 * @param timeNanos simulated time, ns since the run started
 * @param robots every robot, in engine order
 * @param caps every bottle cap, in arena order (held ones where their gripper holds them)
 */
public record Snapshot(long timeNanos, List<RobotView> robots, List<CapView> caps) {
    /** Copies the lists. */
    public Snapshot {
        robots = List.copyOf(robots);
        caps = List.copyOf(caps);
    }

    /** @return simulated time, seconds */
    public double timeSeconds() {
        return timeNanos / 1e9;
    }
}
