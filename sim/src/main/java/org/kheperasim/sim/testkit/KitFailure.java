package org.kheperasim.sim.testkit;

/**
 * A controller that failed, as a run's web page shows it.
 *
 * @param robot the robot's index
 * @param seconds when, simulated s (NaN: not known)
 * @param status one word or two, e.g. {@code threw}
 * @param message what happened
 */
public record KitFailure(int robot, double seconds, String status, String message) {
}
