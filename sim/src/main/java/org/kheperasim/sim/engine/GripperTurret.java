package org.kheperasim.sim.engine;

/** Constants of the gripper turret (khepera-reference.md, "Gripper turret"). */
public final class GripperTurret {
    /** The arm raised, in the turret's 8-bit position units (larger = lower). */
    public static final int ARM_UP = 180;
    /** The arm lowered to the floor. */
    public static final int ARM_DOWN = 250;

    private GripperTurret() {
    }
}
