package org.kheperasim.sim.testkit;

/**
 * A line of a run's console: a controller's message or the simulator's error about a controller.
 *
 * @param timeNanos simulated time, ns
 * @param source the controller's name as the console shows it ({@code Name} or {@code Name#1})
 * @param error true for the simulator's error
 * @param text what it said
 * @param formatted the line as {@code khepera-sim run} prints it
 */
public record KitConsoleLine(long timeNanos, String source, boolean error, String text, String formatted) {
}
