package org.kheperasim.sim.engine.view;

import org.kheperasim.api.GripperState;

/**
 * The gripper turret of one robot at one instant.
 *
 * @param armPosition the arm's position in the turret's 8-bit units, larger = lower
 *     ({@link org.kheperasim.sim.engine.robot.GripperTurret#ARM_UP} raised,
 *     {@link org.kheperasim.sim.engine.robot.GripperTurret#ARM_DOWN} at the floor)
 * @param armMoving true while the arm travels
 * @param fingers the fingers' state
 * @param objectPresent true when something breaks the optical barrier between the fingers
 * @param resistivity what the fingers hold, 0..255; 0 when empty
 * @param heldCap the id of the cap the fingers hold, or -1
 */
public record GripperView(int armPosition, boolean armMoving, GripperState fingers, boolean objectPresent,
        int resistivity, int heldCap) {
}
