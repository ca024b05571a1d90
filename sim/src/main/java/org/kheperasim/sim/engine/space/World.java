package org.kheperasim.sim.engine.space;

import java.util.List;
import java.util.Map;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.ShapeIndex;
import org.kheperasim.sim.engine.view.CapView;

/**
 * The world the robots live in: the arena, its occupancy grid, the grid's distance field (which
 * makes collision tests one lookup), the walls' and lamps' shapes in buckets (which the proximity
 * beams are cast against), and the bottle caps, which move.
 *
 * <p>The arena can be edited during a run ({@link org.kheperasim.sim.engine.Engine#edit}); the grid and the field are
 * updated in place, so everything holding them sees the edit.
 */
public final class World {
    private Arena arena;
    private final OccupancyGrid grid;
    private final DistanceField field;
    private ShapeIndex shapes;
    private int freeCells;

    private final Caps caps;
    private final Bodies bodies;

    /** What rasterising an arena gives: the same for every run of it. */
    private record Raster(OccupancyGrid grid, DistanceField field, ShapeIndex shapes, int freeCells) {
    }

    /** The walls, lights and caps a raster is made from. */
    private record Layout(double width, double height, List<?> walls, List<?> lights, List<?> caps) {
    }

    /** The last arenas' rasters (an evaluation runs one arena many times): each run copies one, never changes it. */
    private static final Map<Layout, Raster> RASTERS = java.util.Collections.synchronizedMap(
            new java.util.LinkedHashMap<>(8, 0.75f, true) {
                @Override
                protected boolean removeEldestEntry(Map.Entry<Layout, Raster> eldest) {
                    return size() > 4;
                }
            });

    /**
     * @param arena an arena
     * @return true when a world of it is quick to build: its raster (grid, distance field) is kept from
     *     an earlier run of the same walls, lights and caps
     */
    public static boolean quickToBuild(Arena arena) {
        return RASTERS.containsKey(layout(arena));
    }

    private static Layout layout(Arena arena) {
        return new Layout(arena.width(), arena.height(), arena.walls(), arena.lights(), arena.caps());
    }

    /** @param arena the arena to build the world from */
    public World(Arena arena) {
        this.arena = arena;
        Layout layout = layout(arena);
        Raster raster = RASTERS.get(layout);
        if (raster == null) {
            OccupancyGrid g = OccupancyGrid.of(arena);
            raster = new Raster(g, DistanceField.of(g), new ShapeIndex(arena, g), countFree(g));
            RASTERS.put(layout, raster);
        }
        // The run's own copies: an edit or a moving cap changes them, never the shared raster.
        this.grid = raster.grid().copy();
        this.field = raster.field().copyFor(grid);
        this.shapes = raster.shapes();
        this.bodies = new Bodies(arena.width(), arena.height());
        this.caps = new Caps(grid, field, bodies);
        caps.load(arena.caps());
        this.freeCells = raster.freeCells();
    }

    private static int countFree(OccupancyGrid grid) {
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

    /**
     * Replace the arena in the middle of a run: walls, lights, regions and start poses come from
     * {@code edited}; cap i of {@code edited} moves cap i unless a gripper holds it. Call it between
     * ticks, holding the turn (through {@link org.kheperasim.sim.engine.Engine#edit}).
     *
     * @param edited the arena as edited, of the same size
     * @throws IllegalArgumentException if the size differs
     */
    public void replaceArena(Arena edited) {
        Arena fixed = new Arena(edited.name(), edited.width(), edited.height(), edited.robots(), edited.walls(),
                edited.lights(), List.of(), edited.regions());
        grid.repaint(fixed);
        this.arena = edited;
        caps.load(edited.caps());
        caps.paintAll();
        field.recompute();
        shapes = new ShapeIndex(fixed, grid);
        freeCells = countFree(grid);
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

    /** @return the walls' and lamps' shapes (as last edited; immutable, so look it up again after an edit) */
    public ShapeIndex shapes() {
        return shapes;
    }

    /** @return the number of floor cells */
    public int freeCells() {
        return freeCells;
    }

    /** @return the number of bottle caps */
    public int capCount() {
        return caps.count();
    }

    /** @return the bottle caps */
    /** @return where the robots' bodies are */
    public Bodies bodies() {
        return bodies;
    }

    public Caps capSet() {
        return caps;
    }

    /** @return every cap as it is now, in arena order */
    public List<CapView> caps() {
        return caps.views();
    }

    /**
     * @return for each named region, in arena order, how many caps lie on the floor with their
     *     centre inside it
     */
    public java.util.Map<String, Integer> capsInRegions() {
        java.util.Map<String, Integer> out = new java.util.LinkedHashMap<>();
        for (org.kheperasim.sim.arena.Region region : arena.regions()) {
            int n = 0;
            for (int i = 0; i < caps.count(); i++) {
                if (caps.heldBy(i) < 0 && region.contains(caps.x(i), caps.y(i))) {
                    n++;
                }
            }
            out.put(region.name(), n);
        }
        return out;
    }
}
