package org.kheperasim.sim.engine.event;

import org.kheperasim.sim.arena.Region;

/**
 * The robot's centre is outside a region it was inside at its last move.
 *
 * @param robot the robot's index
 * @param timeNanos simulated time of the first tick that shows it outside, ns (see {@link EngineEvents}
 *     for the one case where this can be late)
 * @param region the region
 * @param x the robot's centre then, mm
 * @param y the robot's centre then, mm
 */
public record RegionLeft(int robot, long timeNanos, Region region, double x, double y) implements EngineEvent {
}
