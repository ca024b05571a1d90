package org.kheperasim.sim.engine.event;

/**
 * What a robot's body touches.
 *
 * @param kind what sort of thing
 * @param index which one: the wall's index in the arena's walls, the lamp's in its lights, the other
 *     robot's index, the cap's index; -1 for the arena's edge
 */
public record Touched(Kind kind, int index) {
    /** What sort of thing a robot touches. */
    public enum Kind {
        /** A wall of the arena. */
        WALL,
        /** The arena's edge. */
        ARENA_EDGE,
        /** A lamp's body. */
        LAMP,
        /** Another robot. */
        ROBOT,
        /** A cap: one that blocks the robot (the engine's flag), or one it pushes aside (its flag shows none). */
        CAP
    }

    /** The arena's edge. */
    public static final Touched EDGE = new Touched(Kind.ARENA_EDGE, -1);
}
