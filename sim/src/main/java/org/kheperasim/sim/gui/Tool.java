package org.kheperasim.sim.gui;

/** The editing tools of the palette. */
public enum Tool {
    /** Select, move, resize (drag a wall's end) and rotate (drag a robot's heading handle). */
    SELECT("Select / move", "S"),
    /** Drag to draw a wall. */
    WALL("Wall", "W"),
    /** Click to place a lamp. */
    LIGHT("Light", "L"),
    /** Click to place a bottle cap. */
    CAP("Cap", "C"),
    /** Press to place the robot's start, drag to aim it. */
    ROBOT("Robot start", "R");

    private final String label;
    private final String key;

    Tool(String label, String key) {
        this.label = label;
        this.key = key;
    }

    /** @return the palette's label */
    public String label() {
        return label;
    }

    /** @return the key that chooses it */
    public String key() {
        return key;
    }
}
