package org.kheperasim.sim.arena;

import java.util.List;

/**
 * The arena floor as a grid of square cells, each holding the id of what occupies it, as in the
 * WSU simulator's 500 x 500 environment matrix: {@link #FLOOR}, {@link #WALL}, {@link #LIGHT}, and
 * each cap its own id from {@link #FIRST_CAP}.
 *
 * <p>Cells are {@link #CELL_MM} wide, so the paper's 1219.2 mm (4 ft) lab is exactly 500 x 500;
 * other arena sizes get proportionally more or fewer cells of the same size. Column 0 starts at
 * x = 0, row 0 at y = 0. Everything outside the grid reads as {@link #WALL}: the world ends in a
 * wall, so rays always stop.
 *
 * <p>Not thread-safe; the engine owns it.
 */
public final class OccupancyGrid {

    /** Side of one cell, mm: the paper's 4 ft lab drawn as 500 cells. */
    public static final double CELL_MM = 1219.2 / 500;
    /** Id of open floor. */
    public static final int FLOOR = 0;
    /** Id of every wall cell, and of everything outside the grid. */
    public static final int WALL = 1;
    /** Id of every lamp-body cell. */
    public static final int LIGHT = 2;
    /** Id of the first cap; cap {@code i} of the arena's list has id {@code FIRST_CAP + i}. */
    public static final int FIRST_CAP = 3;

    private final int cols;
    private final int rows;
    /** The cells; shared with the grid this one was copied from until this one first changes one. */
    private short[] cells;
    /** Which cells are {@link #FLOOR}, kept with every write; shared as {@link #cells} are. */
    private FloorBits floor;
    private boolean shared;

    /**
     * An all-floor grid.
     *
     * @param cols number of columns, at least 1
     * @param rows number of rows, at least 1
     */
    public OccupancyGrid(int cols, int rows) {
        if (cols < 1 || rows < 1) {
            throw new IllegalArgumentException("grid must be at least 1 x 1 cells, got " + cols + " x " + rows);
        }
        this.cols = cols;
        this.rows = rows;
        this.cells = new short[Math.multiplyExact(cols, rows)];
        this.floor = new FloorBits(cols, rows);
    }

    /**
     * Rasterises an arena: {@code round(width / CELL_MM)} x {@code round(height / CELL_MM)} cells.
     * Walls are painted first, then lights, then caps, each only onto floor, so a cap never
     * overwrites a wall (and lifting a cap later never opens a hole in one).
     *
     * @param arena the arena
     * @return a new grid
     * @throws IllegalArgumentException if the arena has more caps than cell ids can number
     */
    public static OccupancyGrid of(Arena arena) {
        OccupancyGrid g = new OccupancyGrid(colsFor(arena), rowsFor(arena));
        g.paint(arena);
        return g;
    }

    /**
     * @return a new grid with the same cells (a run's own copy of a grid computed before); the cells
     *     are copied only when either grid first changes one, and this one must not change after
     */
    public OccupancyGrid copy() {
        OccupancyGrid g = new OccupancyGrid(cols, rows, cells, floor);
        return g;
    }

    private OccupancyGrid(int cols, int rows, short[] sharedCells, FloorBits sharedFloor) {
        this.cols = cols;
        this.rows = rows;
        this.cells = sharedCells;
        this.floor = sharedFloor;
        this.shared = true;
    }

    /** Before a change: cells shared with another grid become this grid's own. */
    private void own() {
        if (shared) {
            cells = cells.clone();
            floor = floor.copy();
            shared = false;
        }
    }

    /**
     * Rasterise an arena of this grid's size again, in place: every cell is cleared first (an
     * edited arena during a run).
     *
     * @param arena the arena, with {@code colsFor(arena) == cols()} and {@code rowsFor(arena) == rows()}
     * @throws IllegalArgumentException if the arena's size does not match the grid's
     */
    public void repaint(Arena arena) {
        if (colsFor(arena) != cols || rowsFor(arena) != rows) {
            throw new IllegalArgumentException("arena " + arena.name() + " is " + arena.width() + " x "
                    + arena.height() + " mm but the grid is " + cols + " x " + rows
                    + " cells; the size cannot change during a run (start a new run instead)");
        }
        own();
        java.util.Arrays.fill(cells, (short) FLOOR);
        floor.fill();
        paint(arena);
    }

    private void paint(Arena arena) {
        for (Wall w : arena.walls()) {
            WallPainter.paint(this, w);
        }
        for (Light l : arena.lights()) {
            paintDisc(l.x(), l.y(), l.radius(), LIGHT);
        }
        List<Cap> caps = arena.caps();
        for (int i = 0; i < caps.size(); i++) {
            Cap cap = caps.get(i);
            paintDisc(cap.x(), cap.y(), cap.radius(), capId(i));
        }
    }

    private static int colsFor(Arena arena) {
        return (int) Math.max(1, Math.round(arena.width() / CELL_MM));
    }

    private static int rowsFor(Arena arena) {
        return (int) Math.max(1, Math.round(arena.height() / CELL_MM));
    }

    /**
     * @param capIndex index of the cap in {@link Arena#caps()}
     * @return its grid id, {@code FIRST_CAP + capIndex}
     * @throws IllegalArgumentException if the index is negative or too large for a cell id
     */
    public static int capId(int capIndex) {
        if (capIndex < 0 || capIndex > Short.MAX_VALUE - FIRST_CAP) {
            throw new IllegalArgumentException("cap index " + capIndex + " is out of range 0.."
                    + (Short.MAX_VALUE - FIRST_CAP));
        }
        return FIRST_CAP + capIndex;
    }

    /** @return number of columns (cells along x) */
    public int cols() {
        return cols;
    }

    /** @return number of rows (cells along y) */
    public int rows() {
        return rows;
    }

    /** @return side of one cell, mm ({@link #CELL_MM}) */
    public double cellSize() {
        return CELL_MM;
    }

    /**
     * @param col column, any integer
     * @param row row, any integer
     * @return the cell's id; {@link #WALL} outside the grid
     */
    public int id(int col, int row) {
        if (col < 0 || row < 0 || col >= cols || row >= rows) {
            return WALL;
        }
        return cells[row * cols + col];
    }

    /** @return which cells are floor, as they are now (read only; it follows the grid's writes) */
    public FloorBits floorBits() {
        return floor;
    }

    /**
     * @param x point, mm
     * @param y point, mm
     * @return the id of the cell containing the point; {@link #WALL} outside the grid
     */
    public int idAt(double x, double y) {
        return id(col(x), row(y));
    }

    /**
     * Changes one cell, e.g. when a cap moves.
     *
     * @param col column inside the grid
     * @param row row inside the grid
     * @param id  new id, 0..{@link Short#MAX_VALUE}
     * @throws IndexOutOfBoundsException if the cell is outside the grid
     * @throws IllegalArgumentException  if the id is out of range
     */
    public void set(int col, int row, int id) {
        if (col < 0 || row < 0 || col >= cols || row >= rows) {
            throw new IndexOutOfBoundsException("cell (" + col + ", " + row + ") is outside the "
                    + cols + " x " + rows + " grid");
        }
        if (id < 0 || id > Short.MAX_VALUE) {
            throw new IllegalArgumentException("cell id " + id + " is out of range 0.." + Short.MAX_VALUE);
        }
        own();
        cells[row * cols + col] = (short) id;
        floor.set(col, row, id == FLOOR);
    }

    /**
     * @param x mm
     * @return the column containing x (negative or {@code >= cols()} outside the grid)
     */
    public int col(double x) {
        return (int) Math.floor(x / CELL_MM);
    }

    /**
     * @param y mm
     * @return the row containing y (negative or {@code >= rows()} outside the grid)
     */
    public int row(double y) {
        return (int) Math.floor(y / CELL_MM);
    }

    /**
     * @param col column
     * @return x of the column's centre, mm
     */
    public double cellCentreX(int col) {
        return (col + 0.5) * CELL_MM;
    }

    /**
     * @param row row
     * @return y of the row's centre, mm
     */
    public double cellCentreY(int row) {
        return (row + 0.5) * CELL_MM;
    }

    /**
     * Casts a ray through the grid, visiting every cell it passes through (Amanatides and Woo's
     * traversal), and stops at the first cell that is not floor. Allocates nothing.
     *
     * @param x       origin, mm
     * @param y       origin, mm
     * @param dirX    direction, a unit vector (not normalised here)
     * @param dirY    direction, a unit vector
     * @param maxDist how far to look, mm
     * @param hit     filled with the result (on a miss: distance +infinity, id FLOOR, col/row -1)
     * @return distance from the origin to where the ray enters the first non-floor cell, mm;
     *         0 if the origin is already in one; {@link Double#POSITIVE_INFINITY} if there is none
     *         within {@code maxDist}
     */
    public double castRay(double x, double y, double dirX, double dirY, double maxDist, RayHit hit) {
        return march(x, y, dirX, dirY, maxDist, FLOOR, false, hit);
    }

    /**
     * Whether a straight line between two points crosses only floor and cells of one transparent
     * id. Used for light occlusion: pass {@link #LIGHT} so that the lamp's own body does not hide
     * it. Cells the line only touches at a corner count as crossed. Allocates nothing.
     *
     * @param x1            start, mm
     * @param y1            start, mm
     * @param x2            end, mm
     * @param y2            end, mm
     * @param transparentId an id that does not block the line
     * @return true if every cell the segment passes through, both end cells included, is floor or
     *         {@code transparentId}
     */
    public boolean clearLine(double x1, double y1, double x2, double y2, int transparentId) {
        double dx = x2 - x1;
        double dy = y2 - y1;
        double len = Math.sqrt(dx * dx + dy * dy);
        if (len == 0) {
            int id = idAt(x1, y1);
            return id == FLOOR || id == transparentId;
        }
        return march(x1, y1, dx / len, dy / len, len, transparentId, false, null) == Double.POSITIVE_INFINITY;
    }

    /**
     * Whether a lamp's light crosses a straight line: only walls (and the outside) block it. Caps
     * are too low to shade a sensor, and the lamp's own body does not hide it.
     *
     * @param x1 start, mm
     * @param y1 start, mm
     * @param x2 end, mm
     * @param y2 end, mm
     * @return true if no wall cell lies on the segment
     */
    public boolean lightReaches(double x1, double y1, double x2, double y2) {
        double dx = x2 - x1;
        double dy = y2 - y1;
        double len = Math.sqrt(dx * dx + dy * dy);
        if (len == 0) {
            return id(col(x1), row(y1)) != WALL;
        }
        return march(x1, y1, dx / len, dy / len, len, LIGHT, true, null) == Double.POSITIVE_INFINITY;
    }

    /**
     * The grid traversal behind {@link #castRay} and {@link #clearLine}: the distance to the first
     * cell whose id is neither FLOOR nor {@code transparentId} (nor a cap's, when caps are
     * transparent). Each boundary distance is computed
     * from the boundary's position rather than accumulated, so a face on a cell boundary is found
     * at its exact distance.
     */
    private double march(double x, double y, double dirX, double dirY, double maxDist,
                         int transparentId, boolean capsTransparent, RayHit hit) {
        int c = col(x);
        int r = row(y);
        int id = id(c, r);
        if (id != FLOOR && id != transparentId && !(capsTransparent && id >= FIRST_CAP)) {
            return record(hit, 0, id, c, r);
        }
        int stepC = dirX > 0 ? 1 : dirX < 0 ? -1 : 0;
        int stepR = dirY > 0 ? 1 : dirY < 0 ? -1 : 0;
        if (stepC == 0 && stepR == 0) {
            return record(hit, Double.POSITIVE_INFINITY, FLOOR, -1, -1);
        }
        double tMaxX = stepC == 0 ? Double.POSITIVE_INFINITY : boundary(c, stepC, x, dirX);
        double tMaxY = stepR == 0 ? Double.POSITIVE_INFINITY : boundary(r, stepR, y, dirY);
        // From one cell boundary to the next along an axis is a fixed distance along the ray.
        double tDeltaX = stepC == 0 ? Double.POSITIVE_INFINITY : CELL_MM / StrictMath.abs(dirX);
        double tDeltaY = stepR == 0 ? Double.POSITIVE_INFINITY : CELL_MM / StrictMath.abs(dirY);
        while (true) {
            double t;
            if (tMaxX < tMaxY) {
                t = tMaxX;
                c += stepC;
                tMaxX += tDeltaX;
            } else {
                t = tMaxY;
                r += stepR;
                tMaxY += tDeltaY;
            }
            if (t > maxDist) {
                return record(hit, Double.POSITIVE_INFINITY, FLOOR, -1, -1);
            }
            id = c < 0 || r < 0 || c >= cols || r >= rows ? WALL : cells[r * cols + c];
            if (id != FLOOR && id != transparentId && !(capsTransparent && id >= FIRST_CAP)) {
                return record(hit, t > 0 ? t : 0, id, c, r);
            }
        }
    }

    /** Distance along the ray from {@code origin} to the far boundary of cell {@code index}. */
    private static double boundary(int index, int step, double origin, double dir) {
        int edge = step > 0 ? index + 1 : index;
        return (edge * CELL_MM - origin) / dir;
    }

    private static double record(RayHit hit, double distance, int id, int col, int row) {
        if (hit != null) {
            hit.distance = distance;
            hit.id = id;
            hit.col = col;
            hit.row = row;
        }
        return distance;
    }

    /**
     * Paint a cap onto the floor cells of its disc (a cap that has moved).
     *
     * @param capIndex the cap's index
     * @param cx centre, mm
     * @param cy centre, mm
     * @param radius mm
     */
    public void paintCap(int capIndex, double cx, double cy, double radius) {
        paintDisc(cx, cy, radius, capId(capIndex));
    }

    /**
     * Turn a cap's cells back into floor (the cap moves or is picked up). Only the cells of its
     * disc around (cx, cy) are looked at, so this is cheap.
     *
     * @param capIndex the cap's index
     * @param cx where it was painted, mm
     * @param cy where it was painted, mm
     * @param radius mm
     */
    public void eraseCap(int capIndex, double cx, double cy, double radius) {
        int id = capId(capIndex);
        double reach = radius + cellSize();
        int c0 = Math.max(0, col(cx - reach));
        int c1 = Math.min(cols - 1, col(cx + reach));
        int r0 = Math.max(0, row(cy - reach));
        int r1 = Math.min(rows - 1, row(cy + reach));
        for (int r = r0; r <= r1; r++) {
            for (int c = c0; c <= c1; c++) {
                int i = r * cols + c;
                if (cells[i] == id) {
                    own();
                    cells[i] = FLOOR;
                    floor.set(c, r, true);
                }
            }
        }
    }

    /** Paints the cells whose centre lies within {@code radius} of the centre, and the centre's cell. */
    private void paintDisc(double cx, double cy, double radius, int id) {
        int c0 = Math.max(0, col(cx - radius));
        int c1 = Math.min(cols - 1, col(cx + radius));
        int r0 = Math.max(0, row(cy - radius));
        int r1 = Math.min(rows - 1, row(cy + radius));
        double r2 = radius * radius;
        for (int r = r0; r <= r1; r++) {
            double dy = cellCentreY(r) - cy;
            for (int c = c0; c <= c1; c++) {
                double dx = cellCentreX(c) - cx;
                if (dx * dx + dy * dy <= r2) {
                    paintFloor(c, r, id);
                }
            }
        }
        int cc = col(cx);
        int cr = row(cy);
        if (cc >= 0 && cr >= 0 && cc < cols && cr < rows) {
            paintFloor(cc, cr, id);
        }
    }

    /** Sets a cell to {@code id} if it is floor; the cell must lie inside the grid. */
    void paintFloor(int col, int row, int id) {
        int i = row * cols + col;
        if (cells[i] == FLOOR) {
            own();
            cells[i] = (short) id;
            floor.set(col, row, id == FLOOR);
        }
    }

}
