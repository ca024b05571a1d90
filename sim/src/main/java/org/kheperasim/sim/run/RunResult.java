package org.kheperasim.sim.run;

import java.util.List;
import java.util.Map;
import org.kheperasim.sim.host.ControllerStatus;

/**
 * What a run produced, for the one-line summary, the {@code --json} object, benchmarks and tests.
 *
 * @param seed the run's seed
 * @param arena the arena's name
 * @param controller the controller's class name
 * @param simulatedSeconds simulated time reached, s
 * @param wallSeconds real time the run took, s
 * @param traceSha256 SHA-256 of the trace, hex; null when no trace was written
 * @param robots per robot results, in engine order
 * @param capsInRegions for each named region of the arena, in arena order, how many caps lie on
 *     the floor inside it at the end
 * @param caps how many caps the arena has
 */
public record RunResult(long seed, String arena, String controller, double simulatedSeconds, double wallSeconds,
        String traceSha256, List<RobotResult> robots, Map<String, Integer> capsInRegions, int caps) {

    /** Copies the list and the map. */
    public RunResult {
        robots = List.copyOf(robots);
        capsInRegions = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(capsInRegions));
    }

    /**
     * @param name the robot's name
     * @param x final position, mm
     * @param y final position, mm
     * @param headingDeg final heading, degrees
     * @param distanceMm path length, mm
     * @param collisions times a move was stopped by an obstacle
     * @param visitedPercent percentage of floor cells the body covered
     * @param status how the controller ended
     * @param failure what it threw or, when it failed otherwise (hung, broke a rule, ran out of heap), the
     *     error reported; null when it did not fail
     * @param regionsEntered named regions the robot's centre entered, with the first time, s, in arena order
     */
    public record RobotResult(String name, double x, double y, double headingDeg, double distanceMm, int collisions,
            double visitedPercent, ControllerStatus status, String failure, Map<String, Double> regionsEntered) {
        /** Copies the map. */
        public RobotResult {
            regionsEntered = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(regionsEntered));
        }
    }

    /** @return simulated seconds per wall second */
    public double realTimeFactor() {
        return wallSeconds <= 0 ? Double.POSITIVE_INFINITY : simulatedSeconds / wallSeconds;
    }

    /** @return the first robot's result */
    public RobotResult first() {
        return robots.get(0);
    }
}
