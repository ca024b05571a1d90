package org.kheperasim.sim.arena;

/**
 * What a ray cast on the {@link OccupancyGrid} struck. Mutable and reused by the caller, so that
 * casting rays every tick allocates nothing.
 */
public final class RayHit {

    /** Distance from the ray's origin to where it enters the struck cell, mm; +infinity on a miss. */
    public double distance = Double.POSITIVE_INFINITY;
    /** Id of the struck cell ({@link OccupancyGrid#WALL}, a light, a cap); FLOOR on a miss. */
    public int id = OccupancyGrid.FLOOR;
    /** Column of the struck cell (may lie outside the grid, which is wall); -1 on a miss. */
    public int col = -1;
    /** Row of the struck cell (may lie outside the grid, which is wall); -1 on a miss. */
    public int row = -1;

    /** @return true if the last cast struck something */
    public boolean isHit() {
        return distance != Double.POSITIVE_INFINITY;
    }
}
