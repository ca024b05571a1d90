package org.kheperasim.sim.engine.robot;

/**
 * Geometry and constants of the gripper turret (khepera-reference.md, "Gripper turret"). Lengths
 * are in the robot's frame: x forward from the centre, y to the left, mm. The turret's manual was
 * not found; the finger sizes are chosen so that a standard cap (radius 9 mm) fits between the
 * open fingers with about 5 mm to spare on either side.
 */
public final class GripperTurret {
    /** The arm raised, in the turret's 8-bit position units (larger = lower). */
    public static final int ARM_UP = 180;
    /** The arm lowered to the floor. */
    public static final int ARM_DOWN = 250;
    /** Below this position (numerically above) the fingers reach down to the caps. */
    public static final int ARM_LOW = 215;
    /** Where each finger begins (inside the body), mm ahead of the centre. */
    public static final double FINGER_BASE_MM = 24;
    /** Where each finger ends, mm ahead of the centre. */
    public static final double FINGER_TIP_MM = 50;
    /** Half the thickness of a finger, mm. */
    public static final double FINGER_RADIUS_MM = 2;
    /** Distance of each open finger's centre line from the robot's axis, mm. */
    public static final double OPEN_HALF_GAP_MM = 16;
    /** Where a gripped cap's centre is, and where the optical barrier crosses, mm ahead of the centre. */
    public static final double GRIP_MM = 36.5;
    /**
     * How far the open fingers' tips reach from the robot's centre, mm (about 54.5): the farthest
     * part of the lowered gripper but for a large cap it holds (see {@code CapContacts.reachMm}).
     */
    public static final double REACH_MM = StrictMath.hypot(FINGER_TIP_MM, OPEN_HALF_GAP_MM) + FINGER_RADIUS_MM;

    private GripperTurret() {
    }
}
