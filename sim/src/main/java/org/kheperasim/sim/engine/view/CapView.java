package org.kheperasim.sim.engine.view;

/**
 * A bottle cap at one instant.
 *
 * @param id the cap's index in the arena's cap list (its grid id is {@code FIRST_CAP + id})
 * @param x centre, mm (for a held cap: where the gripper holds it)
 * @param y centre, mm
 * @param radius mm
 * @param heldBy the id of the robot whose gripper holds it, or -1 when it lies on the floor
 */
public record CapView(int id, double x, double y, double radius, int heldBy) {
    /** @return true when a gripper holds the cap */
    public boolean held() {
        return heldBy >= 0;
    }
}
