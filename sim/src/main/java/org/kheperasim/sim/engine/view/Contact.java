package org.kheperasim.sim.engine.view;

/**
 * The collision flag: which side of the robot touches an obstacle, in the robot's frame (the
 * paper's section 5.1). Eight sectors of 45° each.
 */
public enum Contact {
    /** Nothing touches the robot. */
    NONE,
    FRONT, FRONT_LEFT, LEFT, BACK_LEFT, BACK, BACK_RIGHT, RIGHT, FRONT_RIGHT;

    private static final Contact[] SECTORS = {FRONT, FRONT_LEFT, LEFT, BACK_LEFT, BACK, BACK_RIGHT, RIGHT, FRONT_RIGHT};

    /**
     * @param relativeRad direction of the contact point seen from the robot's centre, radians
     *     counter-clockwise from straight ahead (any range)
     * @return the sector it falls in
     */
    public static Contact ofAngle(double relativeRad) {
        double turns = relativeRad / (2 * StrictMath.PI);
        turns -= StrictMath.floor(turns);
        int sector = (int) StrictMath.floor(turns * 8 + 0.5) & 7;
        return SECTORS[sector];
    }
}
