package org.kheperasim.api;

import org.kheperasim.api.spi.RobotPort;

/**
 * The gripper turret: an arm that goes up and down, two fingers that open and close, an optical
 * barrier between the fingers and a resistivity sensor for what they hold. A live view.
 *
 * <p>The arm and fingers take time to move; the state read here follows the mechanics (an arm
 * still travelling down is not yet {@link ArmPosition#DOWN}).
 */
public final class Gripper {
    private final RobotPort port;

    Gripper(RobotPort port) {
        this.port = port;
    }

    /** Start raising the arm. */
    public void raiseArm() {
        port.setArmDown(false);
    }

    /** Start lowering the arm to the floor. */
    public void lowerArm() {
        port.setArmDown(true);
    }

    /** @param position where the arm should go */
    public void setArmPosition(ArmPosition position) {
        port.setArmDown(position == ArmPosition.DOWN);
    }

    /** @return where the arm last came to rest (while moving, the position it left) */
    public ArmPosition getArmPosition() {
        return port.armDown() ? ArmPosition.DOWN : ArmPosition.UP;
    }

    /** @return true while the arm is travelling */
    public boolean isArmMoving() {
        return port.armMoving();
    }

    /** Open the fingers (drops what they hold). */
    public void openGripper() {
        port.setFingersClosed(false);
    }

    /** Close the fingers (grabs what is between them). */
    public void closeGripper() {
        port.setFingersClosed(true);
    }

    /** @return whether the fingers are open or closed */
    public GripperState getGripperState() {
        return port.fingersClosed() ? GripperState.CLOSED : GripperState.OPEN;
    }

    /** @return true when something breaks the optical barrier between the fingers */
    public boolean isObjectPresent() {
        return port.objectPresent();
    }

    /** @return resistivity of the held object, 0..255; 0 when the fingers hold nothing */
    public int getResistivity() {
        return port.resistivity();
    }
}
