package org.kheperasim.sim.arena;

/**
 * How far every point of the floor is from the nearest fixed obstacle: the exact Euclidean
 * distance transform of an {@link OccupancyGrid}'s wall and light cells, with everything outside
 * the grid counting as obstacle, plus the nearest obstacle cell itself (the feature transform).
 * Caps move, so they take no part: the engine tests them one by one, as discs.
 *
 * <p>Computed in linear time by Felzenszwalb and Huttenlocher's method: the squared distance is
 * the lower envelope of parabolas, taken first down each column and then along each row, on a copy
 * of the grid padded by one obstacle cell on every side. A 500 x 500 grid takes a few
 * milliseconds. Queries are O(1) and allocate nothing.
 *
 * <p>The field is a snapshot: after editing the grid's walls or lights call {@link #recompute()}.
 * Not thread-safe.
 */
public final class DistanceField {

    private static final int INF = Integer.MAX_VALUE;

    private final OccupancyGrid grid;
    /** Padded width and height: the grid plus one obstacle cell on every side. */
    private final int pw;
    private final int ph;
    /** Squared distance in cells from each padded cell's centre to its nearest obstacle centre. */
    private int[] dist2;
    /**
     * For each padded cell, the lower bound of the clearance that {@link #clearanceBelow} returns
     * for a point in it, in steps of {@link #BELOW_STEP_MM} (unsigned, saturating): a byte, so that
     * the table is a quarter of the grid's size and stays in the cache.
     */
    private byte[] below;
    /**
     * Padded column and row of each padded cell's nearest obstacle cell, packed as
     * {@code row << 16 | col} (a grid has fewer than 65,534 columns), so reading them takes no division.
     */
    private int[] nearest;
    /** The three arrays above are shared with the field this one was copied from until it is recomputed. */
    private boolean shared;

    // Scratch for the one-dimensional transform and the column sweeps, a row long.
    private final int[] f;
    private final int[] out;
    private final int[] arg;
    private final int[] hull;
    private final double[] bound;
    private final int[] lineNearest;

    private DistanceField(OccupancyGrid grid) {
        this(grid, null);
    }

    /** @param from a field of a grid with the same cells, whose arrays this one shares; null to make its own */
    private DistanceField(OccupancyGrid grid, DistanceField from) {
        this.grid = grid;
        this.pw = grid.cols() + 2;
        this.ph = grid.rows() + 2;
        if (pw > 0xFFFF || ph > 0xFFFF) {
            throw new IllegalArgumentException("a distance field holds at most 65,533 x 65,533 cells, not "
                    + grid.cols() + " x " + grid.rows());
        }
        this.dist2 = from != null ? from.dist2 : new int[pw * ph];
        this.below = from != null ? from.below : new byte[pw * ph];
        this.nearest = from != null ? from.nearest : new int[pw * ph];
        this.shared = from != null;
        // Only rows go through the envelope, and the column sweeps keep one value per column.
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
        DistanceField field = new DistanceField(grid);
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
        // Shared until the copy is recomputed (an edit); this one must not be recomputed after.
        return new DistanceField(copy, this);
    }

    /** Recomputes the whole field from the grid's current cells, reusing all storage. */
    public void recompute() {
        if (shared) {
            dist2 = new int[dist2.length];
            below = new byte[below.length];
            nearest = new int[nearest.length];
            shared = false;
        }
        // Pass 1, down each padded column: distance to the nearest obstacle in the same column (the
        // one above on a tie). Obstacles have no extent here, so two sweeps over the rows find it,
        // reading the grid in its own order: downwards the nearest above, upwards the nearest below.
        // (A method per row, so that a cold JVM compiles it soon.)
        for (int y = 0; y < ph; y++) {
            nearestAbove(y);
        }
        for (int y = ph - 1; y >= 0; y--) {
            nearestBelow(y);
        }
        // Pass 2, along each padded row: combine the column distances.
        for (int y = 0; y < ph; y++) {
            combineRow(y * pw);
            belowRow(y * pw);
        }
    }

    /** Pass 2 along the row starting at {@code base}: the nearest obstacle of all the columns'. */
    private void combineRow(int base) {
        for (int x = 0; x < pw; x++) {
            f[x] = dist2[base + x];
            lineNearest[x] = nearest[base + x];
        }
        envelope(pw);
        for (int x = 0; x < pw; x++) {
            int q = arg[x];
            dist2[base + x] = out[x];
            nearest[base + x] = lineNearest[q] << 16 | q;
        }
    }

    /** Row y of pass 1, downwards: {@code lineNearest[x]} is the last obstacle row seen in column x. */
    private void nearestAbove(int y) {
        int base = y * pw;
        for (int x = 0; x < pw; x++) {
            if (isObstacle(x, y)) {
                lineNearest[x] = y;
            }
            long d = y - lineNearest[x];   // row 0 is padding: an obstacle above is always found
            // Far above, the square may pass an int's range; the obstacle below is then nearer (the
            // nearest of the two is at most half a column away, 32,767 cells) and replaces it.
            dist2[base + x] = (int) StrictMath.min(d * d, Integer.MAX_VALUE);
            nearest[base + x] = lineNearest[x];   // for now: the obstacle's row
        }
    }

    /** Row y of pass 1, upwards: an obstacle below that is strictly nearer replaces the one above. */
    private void nearestBelow(int y) {
        int base = y * pw;
        for (int x = 0; x < pw; x++) {
            if (dist2[base + x] == 0) {
                lineNearest[x] = y;
            }
            long d = lineNearest[x] - y;   // the last row is padding too
            if (d * d < dist2[base + x]) {
                dist2[base + x] = (int) (d * d);
                nearest[base + x] = lineNearest[x];
            }
        }
    }

    private void belowRow(int base) {
        for (int i = base; i < base + pw; i++) {
            int d2 = dist2[i];
            below[i] = d2 < BELOW_OF.length ? BELOW_OF[d2] : (byte) 255;
        }
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
        int n = nearest[(r + 1) * pw + c + 1];
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
        return (below[(r + 1) * pw + c + 1] & 0xFF) * BELOW_STEP_MM;
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
            int base = (r + dr) * pw + c;
            for (int dc = 0; dc <= 2; dc++) {
                int n = nearest[base + dc];
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
        return grid.cellCentreX((nearest[(r + 1) * pw + c + 1] & 0xFFFF) - 1);
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
        return grid.cellCentreY((nearest[(r + 1) * pw + c + 1] >>> 16) - 1);
    }

    private boolean isObstacle(int px, int py) {
        return px == 0 || py == 0 || px == pw - 1 || py == ph - 1
                || isFixed(grid.id(px - 1, py - 1));
    }

    private static boolean isFixed(int id) {
        return id != OccupancyGrid.FLOOR && id < OccupancyGrid.FIRST_CAP;
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
