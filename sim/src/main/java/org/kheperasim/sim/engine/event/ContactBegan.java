package org.kheperasim.sim.engine.event;

import org.kheperasim.sim.engine.view.Contact;

/**
 * The robot's body began touching something: the first tick at which the engine's contact flag
 * shows it (or shows a different thing touched).
 *
 * @param robot the robot's index
 * @param timeNanos simulated time of that tick, ns
 * @param touched what it touches
 * @param side the side of the robot that touches, in its own frame (never {@link Contact#NONE})
 * @param x the robot's centre then, mm
 * @param y the robot's centre then, mm
 */
public record ContactBegan(int robot, long timeNanos, Touched touched, Contact side, double x, double y)
        implements EngineEvent {
}
