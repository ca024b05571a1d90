package org.kheperasim.sim.task;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kheperasim.sim.engine.Engine;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.run.RunResult;

/**
 * What a run knows that a task can be scored on, for all robots together.
 *
 * @param timeSeconds      simulated time so far (or at the end), s
 * @param regionsEntered   every region some robot's centre entered, with the earliest entry, s
 * @param visitedPercent   the largest share of the floor one robot's body covered, percent
 * @param capsInRegions    for each region, the caps lying on the floor inside it
 * @param caps             how many caps the arena has
 */
public record RunFacts(double timeSeconds, Map<String, Double> regionsEntered, double visitedPercent,
        Map<String, Integer> capsInRegions, int caps) {

    /** Copies the maps. */
    public RunFacts {
        regionsEntered = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(regionsEntered));
        capsInRegions = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(capsInRegions));
    }

    /**
     * @param result a finished run
     * @return its facts
     */
    public static RunFacts of(RunResult result) {
        Map<String, Double> entered = new LinkedHashMap<>();
        double visited = 0;
        for (RunResult.RobotResult r : result.robots()) {
            merge(entered, r.regionsEntered());
            visited = StrictMath.max(visited, r.visitedPercent());
        }
        return new RunFacts(result.simulatedSeconds(), entered, visited, result.capsInRegions(), result.caps());
    }

    /**
     * The facts of a run as it goes, for a live score. Call it on the thread that steps the engine
     * (or while the engine is paused): it reads the engine's robots and caps.
     *
     * @param engine the running engine
     * @return its facts now
     */
    public static RunFacts live(Engine engine) {
        Map<String, Double> entered = new LinkedHashMap<>();
        double visited = 0;
        List<SimRobot> robots = engine.robots();
        for (SimRobot r : robots) {
            merge(entered, r.regionsEntered());
            visited = StrictMath.max(visited, r.visitedPercent());
        }
        return new RunFacts(engine.timeNanos() / 1e9, entered, visited, engine.world().capsInRegions(),
                engine.world().capCount());
    }

    private static void merge(Map<String, Double> into, Map<String, Double> entered) {
        entered.forEach((name, t) -> into.merge(name, t, StrictMath::min));
    }
}
