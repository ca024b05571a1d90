package org.kheperasim.testing;

import java.util.Optional;

/**
 * One bottle cap of the arena over a run: where it started and ended, and when it first moved.
 *
 * @param id the cap's index, 0 for the arena's first {@code cap} line
 * @param startX centre at the start, mm
 * @param startY centre at the start, mm
 * @param endX centre at the end (where the gripper holds it, if one does), mm
 * @param endY centre at the end, mm
 * @param firstMoved the first sample at which it had moved or was held, or empty when it never moved
 * @param heldAtEnd the index of the robot holding it at the end, or -1 when it lies on the floor
 * @param regionAtEnd the first region of the arena (in file order) it lies in at the end, or empty
 *     (a held cap lies in none)
 */
public record Cap(int id, double startX, double startY, double endX, double endY, Optional<SimTime> firstMoved,
        int heldAtEnd, Optional<String> regionAtEnd) {

    /** @return true when the cap moved or was picked up during the run */
    public boolean moved() {
        return firstMoved.isPresent();
    }

    /** @return how far the cap ended from where it started, mm */
    public double displacementMm() {
        return StrictMath.hypot(endX - startX, endY - startY);
    }
}
