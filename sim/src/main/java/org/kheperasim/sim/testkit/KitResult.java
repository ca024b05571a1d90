package org.kheperasim.sim.testkit;

import java.util.List;
import java.util.Map;

/**
 * What a live run made.
 *
 * @param trace its trace, as {@code khepera-sim run --trace FILE} writes it
 * @param simulatedSeconds how long it ran, simulated s
 * @param robots each robot, in the arena's order
 * @param score the arena's tasks' score
 */
public record KitResult(String trace, double simulatedSeconds, List<Robot> robots, KitScore score) {
    /** How a robot's controller stands at the end. */
    public enum Status {
        /** It never started. */
        NOT_STARTED,
        /** It was still running. */
        RUNNING,
        /** It returned. */
        FINISHED,
        /** It threw. */
        FAILED,
        /** It stopped making API calls. */
        HUNG,
        /** It was stopped. */
        STOPPED,
        /** It broke a rule of the simulator. */
        BROKE_RULE,
        /** It ran out of memory. */
        EXCEEDED_MEMORY
    }

    /**
     * @param name the robot's controller name, as the console shows it
     * @param status how its controller stands
     * @param failure what it failed with, or null
     * @param collisions how many moves an obstacle stopped
     * @param distanceMm its centre's path length, mm
     * @param visitedPercent the share of the floor its body covered, %
     * @param regionsEntered the regions its centre entered, with the first entry's time, s, in arena order
     * @param contacts what it touched and when, from the engine's events, in time order
     */
    public record Robot(String name, Status status, String failure, int collisions, double distanceMm,
            double visitedPercent, Map<String, Double> regionsEntered, List<KitContact> contacts) {
    }
}
