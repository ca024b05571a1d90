package org.kheperasim.sim.engine.event;

/**
 * The robot's body stopped touching what a {@link ContactBegan} said it touched: the first tick at
 * which the engine's contact flag no longer shows it.
 *
 * @param robot the robot's index
 * @param timeNanos simulated time of that tick, ns
 * @param touched what it touched
 * @param x the robot's centre where it was last seen touching, mm
 * @param y the robot's centre where it was last seen touching, mm
 */
public record ContactEnded(int robot, long timeNanos, Touched touched, double x, double y) implements EngineEvent {
}
