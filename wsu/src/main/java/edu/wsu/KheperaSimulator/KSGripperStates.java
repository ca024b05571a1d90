package edu.wsu.KheperaSimulator;

/**
 * The arm and finger states of the gripper turret, as the WSU Khepera Simulator numbers them. The
 * values are compile-time constants, so they are copied into controllers compiled against them;
 * they never change.
 */
public class KSGripperStates {
    /** The arm is raised (its state at the start of a run). */
    public static final int ARM_UP = 20;
    /** The arm is lowered to the floor. */
    public static final int ARM_DOWN = 21;
    /** The fingers are open (their state at the start of a run). */
    public static final int GRIP_OPEN = 22;
    /** The fingers are closed. */
    public static final int GRIP_CLOSED = 23;
}
