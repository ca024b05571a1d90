package org.kheperasim.sim.testkit;

/**
 * A time a robot's body touched something, from the engine's events: exact ticks.
 *
 * @param fromNanos the first tick it touched, ns
 * @param toNanos the last tick it touched, ns (the run's end when it still touched then)
 * @param kind what it touched
 * @param index which one: a wall's, lamp's, robot's or cap's index; -1 for the arena's edge
 * @param side the side of the robot that touched first, in its own frame: {@code FRONT}, {@code FRONT_LEFT}, ...
 * @param x the robot's centre at {@code fromNanos}, mm
 * @param y the robot's centre at {@code fromNanos}, mm
 */
public record KitContact(long fromNanos, long toNanos, Kind kind, int index, String side, double x, double y) {
    /** What sort of thing was touched. */
    public enum Kind {
        /** A wall. */
        WALL,
        /** The arena's edge. */
        ARENA_EDGE,
        /** A lamp's body. */
        LAMP,
        /** Another robot. */
        ROBOT,
        /** A cap, blocking the robot or pushed by it. */
        CAP
    }
}
