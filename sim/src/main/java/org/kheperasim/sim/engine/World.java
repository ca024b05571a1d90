package org.kheperasim.sim.engine;

import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.OccupancyGrid;

/**
 * The static world the robots live in: the arena, its occupancy grid and the grid's distance field
 * (which makes collision tests one lookup and lets a sensor skip its beams when nothing is near).
 */
public final class World {
    private final Arena arena;
    private final OccupancyGrid grid;
    private final DistanceField field;
    private final int freeCells;

    /** @param arena the arena to build the world from */
    public World(Arena arena) {
        this.arena = arena;
        this.grid = OccupancyGrid.of(arena);
        this.field = DistanceField.of(grid);
        int free = 0;
        for (int r = 0; r < grid.rows(); r++) {
            for (int c = 0; c < grid.cols(); c++) {
                if (grid.id(c, r) == OccupancyGrid.FLOOR) {
                    free++;
                }
            }
        }
        this.freeCells = free;
    }

    /** @return the arena */
    public Arena arena() {
        return arena;
    }

    /** @return the occupancy grid */
    public OccupancyGrid grid() {
        return grid;
    }

    /** @return the distance field of the grid's obstacles */
    public DistanceField field() {
        return field;
    }

    /** @return the number of floor cells */
    public int freeCells() {
        return freeCells;
    }
}
