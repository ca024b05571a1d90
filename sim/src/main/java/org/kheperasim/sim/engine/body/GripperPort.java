package org.kheperasim.sim.engine.body;

import org.kheperasim.api.ArmPosition;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.engine.view.GripperView;

/** The gripper turret of a robot as its controller and a protocol client read it. */
public final class GripperPort {
    private final GripperModel gripper;

    public GripperPort(GripperModel gripper) {
        this.gripper = gripper;
    }

    /** @return where the arm last came to rest (while moving: the position it left) */
    public ArmPosition armRest() {
        return gripper.armRest();
    }

    /** @return the arm's position now, in the turret's 8-bit units (larger = lower) */
    public int armPosition() {
        return gripper.armPosition();
    }

    /** @return true while the arm travels */
    public boolean armMoving() {
        return gripper.armMoving();
    }

    /** @return the state the fingers last reached (while moving: the state they left) */
    public GripperState fingers() {
        return gripper.fingers();
    }

    /** @return the id of the cap the fingers hold, or -1 */
    public int heldCap() {
        return gripper.heldCap();
    }

    /** @return true when something breaks the optical barrier between the fingers */
    public boolean objectPresent() {
        return gripper.objectPresent();
    }

    /** @return resistivity of what the fingers hold, 0..255; 0 when they hold nothing */
    public int resistivity() {
        return gripper.resistivity();
    }

    /** @return the turret's state now */
    public GripperView view() {
        return gripper.view();
    }
}
