package org.kheperasim.sim.engine.view;

import java.util.List;

/**
 * The world at one instant, as the engine publishes it to listeners (the window, the trace
 * writer, metrics, tests). Immutable: a listener may keep it as long as it likes.
 *
 * @param timeNanos simulated time, ns since the run started
 * @param robots every robot, in engine order
 * @param caps every bottle cap, in arena order (held ones where their gripper holds them)
 * @param vision the last image each robot's vision turret gave its controller, in robot order, for the
 *     robots whose turret has been read
 */
public record Snapshot(long timeNanos, List<RobotView> robots, List<CapView> caps, List<VisionView> vision) {
    /** Copies the lists. */
    public Snapshot {
        robots = List.copyOf(robots);
        caps = List.copyOf(caps);
        vision = List.copyOf(vision);
    }

    /** A snapshot in which no vision turret has been read. */
    public Snapshot(long timeNanos, List<RobotView> robots, List<CapView> caps) {
        this(timeNanos, robots, caps, List.of());
    }

    /** @param robot a robot's index @return the last image its vision turret gave, if it has been read */
    public java.util.Optional<VisionView> vision(int robot) {
        for (VisionView v : vision) {
            if (v.robot() == robot) {
                return java.util.Optional.of(v);
            }
        }
        return java.util.Optional.empty();
    }

    /** @return simulated time, seconds */
    public double timeSeconds() {
        return timeNanos / 1e9;
    }
}
