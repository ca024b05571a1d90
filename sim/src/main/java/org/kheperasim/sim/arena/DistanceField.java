package org.kheperasim.sim.arena;

/**
 * How far every point of the floor is from the nearest fixed obstacle: the exact Euclidean
 * distance transform of an {@link OccupancyGrid}'s wall and light cells, with everything outside
 * the grid counting as obstacle, plus the nearest obstacle cell itself (the feature transform).
 * Caps move, so they take no part: the engine tests them one by one, as discs.
 *
 * <p>Computed in linear time by Felzenszwalb and Huttenlocher's method: the squared distance is
 * the lower envelope of parabolas, taken first down each column (here from the obstacles' runs of
 * rows, {@link ObstacleRuns}) and then along each row, on the grid padded by one obstacle cell on
 * every side. A 500 x 500 grid takes a few milliseconds.
 *
 * <p>Kept in tiles of {@value #TILE} x {@value #TILE} cells, and only the tiles within
 * {@value #KEPT_CELLS} cells of an obstacle: memory grows with the walls, not with the floor. A cell
 * of a tile not kept is farther than that from every obstacle; its lower bound ({@link
 * #clearanceBelow}) is the saturated one, and its nearest obstacle is worked out from the runs when
 * asked, the same cell the sweeps would have found (a test compares them cell by cell). Queries
 * allocate nothing; those in kept tiles are O(1).
 *
 * <p>The field is a snapshot: after editing the grid's walls or lights call {@link #recompute()}.
 * Queries only read, so several threads may ask at once; {@link #recompute()} is not thread-safe.
 */
public final class DistanceField {

    private static final int INF = Integer.MAX_VALUE;
    /** Cells along a tile's side, and its power of two. */
    static final int TILE = 64;
    private static final int TILE_SHIFT = 6;
    private static final int TILE_MASK = TILE - 1;
    /**
     * A tile is kept when one of its cells is within this many cells (about 312 mm) of an obstacle:
     * more than the 155 mm where {@link #clearanceBelow} saturates, so that a robot's contacts and
     * most of its clearance look-ups stay in kept tiles.
     */
    static final int KEPT_CELLS = 128;

    private final OccupancyGrid grid;
    /** Padded width and height: the grid plus one obstacle cell on every side. */
    private final int pw;
    private final int ph;
    private final int tilesAcross;
    /** The obstacles as runs: the column sweeps read them, and the cells of tiles not kept ask them. */
    private ObstacleRuns runs;
    /**
     * Per tile (row-major), for each of its padded cells, the lower bound of the clearance that
     * {@link #clearanceBelow} returns for a point in it, in steps of {@link #BELOW_STEP_MM}
     * (unsigned, saturating); null where the tile is not kept (all saturated).
     */
    private byte[][] below;
    /**
     * Per tile, each padded cell's nearest obstacle cell, packed as {@code row << 16 | col} (padded;
     * a grid has fewer than 65,534 columns), so reading it takes no division; null where not kept.
     */
    private int[][] nearest;

    // Scratch for the one-dimensional transform, a row long.
    private final int[] f;
    private final int[] out;
    private final int[] arg;
    private final int[] hull;
    private final double[] bound;
    private final int[] lineNearest;

    /** @param from a field of a grid with the same cells, whose tiles this one shares; null to make its own */
    private DistanceField(OccupancyGrid grid, DistanceField from) {
        this.grid = grid;
        this.pw = grid.cols() + 2;
        this.ph = grid.rows() + 2;
        if (pw > 0xFFFF || ph > 0xFFFF) {
            throw new IllegalArgumentException("a distance field holds at most 65,533 x 65,533 cells, not "
                    + grid.cols() + " x " + grid.rows());
        }
        this.tilesAcross = (pw + TILE - 1) >> TILE_SHIFT;
        if (from != null) {
            this.runs = from.runs;
            this.below = from.below;
            this.nearest = from.nearest;
        }
        this.f = new int[pw];
        this.out = new int[pw];
        this.arg = new int[pw];
        this.hull = new int[pw];
        this.bound = new double[pw];
        this.lineNearest = new int[pw];
    }

    /**
     * Computes the field of a grid. The field keeps a reference to the grid for
     * {@link #recompute()}.
     *
     * @param grid the occupancy grid
     * @return the field, up to date with the grid as it is now
     */
    public static DistanceField of(OccupancyGrid grid) {
        DistanceField field = new DistanceField(grid, null);
        field.recompute();
        return field;
    }

    /**
     * A copy of this field for a copy of its grid (the same cells): a field is costly to compute and
     * the same for every run of an arena, so a run copies one computed before.
     *
     * @param copy a grid with the same cells as this field's
     * @return a field of {@code copy}, equal to this one
     */
    public DistanceField copyFor(OccupancyGrid copy) {
        if (copy.cols() != grid.cols() || copy.rows() != grid.rows()) {
            throw new IllegalArgumentException("a field's copy needs a grid of the same size");
        }
        // The tiles are never written after they are made: a recompute makes new ones.
        return new DistanceField(copy, this);
    }

    /** Recomputes the whole field from the grid's current cells, in new tiles. */
    public void recompute() {
        runs = ObstacleRuns.of(grid);
        int tilesDown = (ph + TILE - 1) >> TILE_SHIFT;
        below = new byte[tilesAcross * tilesDown][];
        nearest = new int[tilesAcross * tilesDown][];
        int[] run = new int[pw];
        for (int x = 0; x < pw; x++) {
            run[x] = runs.firstRun(x);
        }
        int[] bandNearest = new int[TILE * pw];
        byte[] bandBelow = new byte[TILE * pw];
        int[] tileLeast = new int[tilesAcross];
        for (int ty = 0; ty < tilesDown; ty++) {
            java.util.Arrays.fill(tileLeast, INF);
            int y0 = ty << TILE_SHIFT;
            int y1 = StrictMath.min(ph, y0 + TILE);
            for (int y = y0; y < y1; y++) {
                sweepRow(y, run);
                int base = (y - y0) * pw;
                for (int x = 0; x < pw; x++) {
                    int q = arg[x];
                    int d2 = out[x];
                    bandNearest[base + x] = lineNearest[q] << 16 | q;
                    bandBelow[base + x] = d2 < BELOW_OF.length ? BELOW_OF[d2] : (byte) 255;
                    if (d2 < tileLeast[x >> TILE_SHIFT]) {
                        tileLeast[x >> TILE_SHIFT] = d2;
                    }
                }
            }
            keepTiles(ty, y1 - y0, tileLeast, bandNearest, bandBelow);
        }
    }

    /** Padded row y: the columns' nearest obstacles from the runs, then their lower envelope along the row. */
    private void sweepRow(int y, int[] run) {
        for (int x = 0; x < pw; x++) {
            int r = runs.advance(x, run[x], y);
            run[x] = r;
            long c = runs.nearestInColumn(r, y);
            f[x] = (int) (c >>> 32);
            lineNearest[x] = (int) c;
        }
        envelope(pw);
    }

    /** Keeps the tiles of tile row {@code ty} that have a cell within {@link #KEPT_CELLS} of an obstacle. */
    private void keepTiles(int ty, int bandRows, int[] tileLeast, int[] bandNearest, byte[] bandBelow) {
        for (int tx = 0; tx < tilesAcross; tx++) {
            if (tileLeast[tx] >= KEPT_CELLS * KEPT_CELLS) {
                continue;
            }
            int[] n = new int[TILE * TILE];
            byte[] b = new byte[TILE * TILE];
            int x0 = tx << TILE_SHIFT;
            int w = StrictMath.min(pw, x0 + TILE) - x0;
            for (int r = 0; r < bandRows; r++) {
                System.arraycopy(bandNearest, r * pw + x0, n, r << TILE_SHIFT, w);
                System.arraycopy(bandBelow, r * pw + x0, b, r << TILE_SHIFT, w);
            }
            nearest[ty * tilesAcross + tx] = n;
            below[ty * tilesAcross + tx] = b;
        }
    }

    /** @return the nearest obstacle of padded cell (px, py), packed as {@link #nearest} keeps it */
    private int nearestOf(int px, int py) {
        int[] tile = nearest[(py >> TILE_SHIFT) * tilesAcross + (px >> TILE_SHIFT)];
        return tile != null ? tile[(py & TILE_MASK) << TILE_SHIFT | px & TILE_MASK] : runs.nearest(px, py);
    }

    /** @return how many tiles the field keeps, and how many it has in all (for tests and figures) */
    int[] tilesKept() {
        int kept = 0;
        for (int[] t : nearest) {
            kept += t != null ? 1 : 0;
        }
        return new int[] {kept, nearest.length};
    }

    /**
     * Distance from a point to the nearest obstacle: the exact distance from the point to the
     * square of the obstacle cell nearest to the cell containing the point. Within about a cell
     * of the true clearance; O(1), no allocation.
     *
     * @param x point, mm
     * @param y point, mm
     * @return clearance, mm; 0 inside an obstacle cell or outside the grid
     */
    public double clearance(double x, double y) {
        int c = grid.col(x);
        int r = grid.row(y);
        if (c < 0 || r < 0 || c >= grid.cols() || r >= grid.rows()) {
            return 0;
        }
        int n = nearestOf(c + 1, r + 1);
        double left = ((n & 0xFFFF) - 1) * OccupancyGrid.CELL_MM;
        double bottom = ((n >>> 16) - 1) * OccupancyGrid.CELL_MM;
        double dx = Math.max(0, Math.max(left - x, x - (left + OccupancyGrid.CELL_MM)));
        double dy = Math.max(0, Math.max(bottom - y, y - (bottom + OccupancyGrid.CELL_MM)));
        return Math.sqrt(dx * dx + dy * dy);
    }

    /**
     * A lower bound of the distance from a point to the nearest obstacle, for skipping empty
     * space: the distance between the centres of the point's cell and of the obstacle cell nearest
     * to it, less the two cells' half diagonals (and a hair for rounding). Cheaper than
     * {@link #clearance}; never more than the true clearance.
     *
     * @param x point, mm
     * @param y point, mm
     * @return a lower bound of the clearance, mm, at most 255 steps of {@link #BELOW_STEP_MM} (about
     *     155 mm); 0 outside the grid
     */
    public double clearanceBelow(double x, double y) {
        int c = (int) Math.floor(x * INV_CELL);
        int r = (int) Math.floor(y * INV_CELL);
        if (c < 0 || r < 0 || c >= grid.cols() || r >= grid.rows()) {
            return 0;
        }
        // The point may lie a rounding error outside cell (c, r): the hair covers that too.
        int px = c + 1;
        int py = r + 1;
        byte[] tile = below[(py >> TILE_SHIFT) * tilesAcross + (px >> TILE_SHIFT)];
        int steps = tile == null ? 255 : tile[(py & TILE_MASK) << TILE_SHIFT | px & TILE_MASK] & 0xFF;
        return steps * BELOW_STEP_MM;
    }

    private static final double INV_CELL = 1 / OccupancyGrid.CELL_MM;
    /** Two half diagonals of a cell, and 0.01 mm for rounding. */
    private static final double BELOW_MARGIN_MM = StrictMath.sqrt(2) * OccupancyGrid.CELL_MM + 0.01;
    /** The unit of {@link #below}: a quarter cell, mm. */
    private static final double BELOW_STEP_MM = OccupancyGrid.CELL_MM / 4;
    /**
     * {@link #below}'s entry for each squared distance in cells, up to the first that saturates it
     * (about 4,250): the same value computed once per distance instead of once per cell.
     */
    private static final byte[] BELOW_OF = belowTable();

    private static byte[] belowTable() {
        java.io.ByteArrayOutputStream table = new java.io.ByteArrayOutputStream();
        for (int d2 = 0; ; d2++) {
            double bound = Math.sqrt(d2) * OccupancyGrid.CELL_MM - BELOW_MARGIN_MM;
            int steps = StrictMath.max(0, StrictMath.min(255, (int) Math.floor(bound / BELOW_STEP_MM)));
            if (steps == 255) {
                return table.toByteArray();
            }
            table.write(steps);
        }
    }

    /**
     * Like {@link #clearance}, but takes the nearest obstacle of the point's cell and of its eight
     * neighbours, which brings the estimate to within a small fraction of a cell of the true
     * clearance. About nine times the work: use it where precision matters (contact).
     *
     * @param x point, mm
     * @param y point, mm
     * @return clearance, mm; 0 inside an obstacle cell or outside the grid
     */
    public double preciseClearance(double x, double y) {
        int c = grid.col(x);
        int r = grid.row(y);
        if (c < 0 || r < 0 || c >= grid.cols() || r >= grid.rows()) {
            return 0;
        }
        double best = Double.POSITIVE_INFINITY;
        for (int dr = 0; dr <= 2; dr++) {
            for (int dc = 0; dc <= 2; dc++) {
                int n = nearestOf(c + dc, r + dr);
                double left = ((n & 0xFFFF) - 1) * OccupancyGrid.CELL_MM;
                double bottom = ((n >>> 16) - 1) * OccupancyGrid.CELL_MM;
                double dx = Math.max(0, Math.max(left - x, x - (left + OccupancyGrid.CELL_MM)));
                double dy = Math.max(0, Math.max(bottom - y, y - (bottom + OccupancyGrid.CELL_MM)));
                double d = dx * dx + dy * dy;
                if (d < best) {
                    best = d;
                }
            }
        }
        return Math.sqrt(best);
    }

    /**
     * @param x point, mm
     * @param y point, mm
     * @return x of the centre of the obstacle cell nearest to the point's cell, mm (the point's own
     *         cell when it is an obstacle or outside the grid; the padding cell just outside the
     *         grid when the arena's edge is nearest)
     */
    public double nearestObstacleX(double x, double y) {
        int c = grid.col(x);
        int r = grid.row(y);
        if (c < 0 || r < 0 || c >= grid.cols() || r >= grid.rows()) {
            return grid.cellCentreX(c);
        }
        return grid.cellCentreX((nearestOf(c + 1, r + 1) & 0xFFFF) - 1);
    }

    /**
     * @param x point, mm
     * @param y point, mm
     * @return y of the centre of the obstacle cell nearest to the point's cell, mm (see
     *         {@link #nearestObstacleX})
     */
    public double nearestObstacleY(double x, double y) {
        int c = grid.col(x);
        int r = grid.row(y);
        if (c < 0 || r < 0 || c >= grid.cols() || r >= grid.rows()) {
            return grid.cellCentreY(r);
        }
        return grid.cellCentreY((nearestOf(c + 1, r + 1) >>> 16) - 1);
    }

    /**
     * One-dimensional squared distance transform of {@code f[0..n)}: for each position p,
     * {@code out[p] = min over q of (p - q)^2 + f[q]} and {@code arg[p]} is that q. Samples equal
     * to INF take no part. Builds the lower envelope of the parabolas rooted at the samples
     * ({@code hull} holds their roots, {@code bound[k]} where parabola k starts to be lowest), then
     * reads it off left to right. At least one sample must be finite; the padding guarantees it.
     */
    private void envelope(int n) {
        int k = -1;
        for (int q = 0; q < n; q++) {
            if (f[q] == INF) {
                continue;
            }
            double s = Double.NEGATIVE_INFINITY;
            while (k >= 0) {
                int p = hull[k];
                s = ((f[q] + (long) q * q) - (f[p] + (long) p * p)) / (2.0 * (q - p));
                if (s > bound[k]) {
                    break;
                }
                k--;
            }
            k++;
            hull[k] = q;
            bound[k] = k == 0 ? Double.NEGATIVE_INFINITY : s;
        }
        int j = 0;
        for (int p = 0; p < n; p++) {
            while (j < k && bound[j + 1] < p) {
                j++;
            }
            int q = hull[j];
            out[p] = (p - q) * (p - q) + f[q];
            arg[p] = q;
        }
    }
}
