package org.kheperasim.api;

/** The state of the gripper's fingers. */
public enum GripperState {
    /** The fingers are apart. */
    OPEN,
    /** The fingers are together (holding whatever was between them). */
    CLOSED
}
