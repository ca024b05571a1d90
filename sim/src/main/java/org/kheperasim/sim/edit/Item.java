package org.kheperasim.sim.edit;

/**
 * One thing in an arena that can be selected: its kind and its index in the arena's list.
 *
 * @param kind what it is
 * @param index its index in {@code arena.robots()}, {@code walls()}, {@code lights()} or {@code caps()}
 */
public record Item(Kind kind, int index) {
    /** What an item is. */
    public enum Kind {
        /** A robot's start pose. */
        ROBOT,
        /** A wall. */
        WALL,
        /** A lamp. */
        LIGHT,
        /** A bottle cap. */
        CAP
    }
}
