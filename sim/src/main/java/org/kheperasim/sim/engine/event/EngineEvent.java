package org.kheperasim.sim.engine.event;

/**
 * Something that happened to a robot at one tick of a run, as the engine decided it: its body began
 * or stopped touching something, or its centre entered or left a region of the arena (as Tank Royale
 * publishes {@code bot-hit-wall}). Events are immutable and come in the same order on every run of
 * the same inputs: by time, then by robot index, then in the order they happened to the robot.
 */
public sealed interface EngineEvent permits ContactBegan, ContactEnded, RegionEntered, RegionLeft {
    /** @return the robot's index in the engine (the arena's robot order) */
    int robot();

    /**
     * @return simulated time of the tick at which it happened, ns: the first tick whose state (a
     *     snapshot, a trace line) shows it
     */
    long timeNanos();
}
