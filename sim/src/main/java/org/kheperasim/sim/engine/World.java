package org.kheperasim.sim.engine;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.OccupancyGrid;

/**
 * The world the robots live in: the arena, its occupancy grid, the grid's distance field (which
 * makes collision tests one lookup and lets a sensor skip its beams when nothing is near), and the
 * bottle caps, which move.
 *
 * <p>The arena can be edited during a run ({@link Engine#edit}); the grid and the field are
 * updated in place, so everything holding them sees the edit.
 */
public final class World {
    private Arena arena;
    private final OccupancyGrid grid;
    private final DistanceField field;
    private int freeCells;

    // The caps: index i is the arena's cap i, grid id FIRST_CAP + i.
    private double[] capX = new double[0];
    private double[] capY = new double[0];
    private double[] capR = new double[0];
    private int[] capHeldBy = new int[0];

    /** @param arena the arena to build the world from */
    public World(Arena arena) {
        this.arena = arena;
        this.grid = OccupancyGrid.of(arena);
        this.field = DistanceField.of(grid);
        loadCaps(arena.caps());
        this.freeCells = countFree();
    }

    private int countFree() {
        int free = 0;
        for (int r = 0; r < grid.rows(); r++) {
            for (int c = 0; c < grid.cols(); c++) {
                if (grid.id(c, r) == OccupancyGrid.FLOOR) {
                    free++;
                }
            }
        }
        return free;
    }

    private void loadCaps(List<Cap> caps) {
        int n = caps.size();
        int old = capX.length;
        capX = Arrays.copyOf(capX, n);
        capY = Arrays.copyOf(capY, n);
        capR = Arrays.copyOf(capR, n);
        capHeldBy = Arrays.copyOf(capHeldBy, n);
        for (int i = 0; i < n; i++) {
            if (i >= old) {
                capHeldBy[i] = -1;
            }
            if (capHeldBy[i] < 0) {
                capX[i] = caps.get(i).x();
                capY[i] = caps.get(i).y();
            }
            capR[i] = caps.get(i).radius();
        }
    }

    /**
     * Replace the arena in the middle of a run: walls, lights, regions and start poses come from
     * {@code edited}; cap i of {@code edited} moves cap i unless a gripper holds it. Call it between
     * ticks, holding the turn (through {@link Engine#edit}).
     *
     * @param edited the arena as edited, of the same size
     * @throws IllegalArgumentException if the size differs
     */
    void replaceArena(Arena edited) {
        loadCaps(edited.caps());
        List<Cap> placed = new ArrayList<>(capX.length);
        for (int i = 0; i < capX.length; i++) {
            placed.add(new Cap(capX[i], capY[i], capR[i]));
        }
        Arena painted = new Arena(edited.name(), edited.width(), edited.height(), edited.robots(), edited.walls(),
                edited.lights(), List.of(), edited.regions());
        grid.repaint(painted);
        this.arena = edited;
        for (int i = 0; i < capX.length; i++) {
            if (capHeldBy[i] < 0) {
                paintCap(i);
            }
        }
        field.recompute();
        freeCells = countFree();
    }

    private void paintCap(int i) {
        grid.paintCap(i, capX[i], capY[i], capR[i]);
    }

    /** @return the arena (as last edited) */
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

    /** @return the number of caps */
    public int capCount() {
        return capX.length;
    }

    /** @return every cap as it is now, in arena order */
    public List<CapView> caps() {
        List<CapView> out = new ArrayList<>(capX.length);
        for (int i = 0; i < capX.length; i++) {
            out.add(new CapView(i, capX[i], capY[i], capR[i], capHeldBy[i]));
        }
        return out;
    }
}
