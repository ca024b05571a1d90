package org.kheperasim.api;

/** Where the gripper turret's arm is asked to go, or where it last came to rest. */
public enum ArmPosition {
    /** Raised: the fingers are clear of the floor and of caps. */
    UP,
    /** Lowered: the fingers are at floor level, ready to grab a cap. */
    DOWN
}
