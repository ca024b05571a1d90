package org.kheperasim.sim.engine.event;

import org.kheperasim.sim.arena.Region;

/**
 * The robot's centre is inside a region of the arena it was not in at its last move (or it starts
 * there: then the time is the watch's start).
 *
 * @param robot the robot's index
 * @param timeNanos simulated time of the first tick that shows it inside, ns
 * @param region the region
 * @param x the robot's centre then, mm
 * @param y the robot's centre then, mm
 */
public record RegionEntered(int robot, long timeNanos, Region region, double x, double y) implements EngineEvent {
}
