package org.kheperasim.sim.arena;

/**
 * The fixed obstacle cells of an {@link OccupancyGrid} padded by one obstacle cell on every side
 * (walls and lamps; caps move and take no part), column by column as runs of rows: memory that grows
 * with the walls, not with the floor. {@link DistanceField} sweeps them row by row, and asks them for
 * the nearest obstacle of a cell whose part of the field it does not keep.
 *
 * <p>Rows and columns here are padded ones: the grid's cell (c, r) is (c + 1, r + 1); row 0, the last
 * row and columns 0 and the last are the padding. Immutable, so safe to read from several threads.
 */
final class ObstacleRuns {

    /** Padded width. */
    private final int pw;
    /** Column x's runs are {@code first[x]} to {@code first[x + 1]} (exclusive), top to bottom. */
    private final int[] first;
    /** Each run's first and last row. */
    private final int[] start;
    private final int[] end;

    private ObstacleRuns(int pw, int[] first, int[] start, int[] end) {
        this.pw = pw;
        this.first = first;
        this.start = start;
        this.end = end;
    }

    /** The runs of a grid's fixed obstacles as it is now (read row by row, in the grid's own order). */
    static ObstacleRuns of(OccupancyGrid grid) {
        int pw = grid.cols() + 2;
        int[] count = new int[pw];
        scan(grid, count, null, null, null);
        int[] first = new int[pw + 1];
        for (int x = 0; x < pw; x++) {
            first[x + 1] = first[x] + count[x];
        }
        int[] start = new int[first[pw]];
        int[] end = new int[first[pw]];
        scan(grid, count, first, start, end);
        return new ObstacleRuns(pw, first, start, end);
    }

    /**
     * One pass over the padded rows: counts each column's runs into {@code count} (when {@code first} is
     * null), or writes them out.
     */
    private static void scan(OccupancyGrid grid, int[] count, int[] first, int[] start, int[] end) {
        int pw = grid.cols() + 2;
        int ph = grid.rows() + 2;
        boolean[] inRun = new boolean[pw];
        int[] next = first == null ? null : java.util.Arrays.copyOf(first, pw);
        if (first == null) {
            java.util.Arrays.fill(count, 0);
        }
        for (int y = 0; y < ph; y++) {
            boolean padRow = y == 0 || y == ph - 1;
            for (int x = 0; x < pw; x++) {
                boolean obstacle = padRow || x == 0 || x == pw - 1 || isFixed(grid.id(x - 1, y - 1));
                if (obstacle && !inRun[x]) {
                    if (first == null) {
                        count[x]++;
                    } else {
                        start[next[x]] = y;
                    }
                } else if (!obstacle && inRun[x] && first != null) {
                    end[next[x]++] = y - 1;
                }
                inRun[x] = obstacle;
            }
        }
        if (first != null) {
            for (int x = 0; x < pw; x++) {
                end[next[x]] = ph - 1;   // the last row is padding: every column's last run ends there
            }
        }
    }

    private static boolean isFixed(int id) {
        return id != OccupancyGrid.FLOOR && id < OccupancyGrid.FIRST_CAP;
    }

    /** @return the index of column x's first run */
    int firstRun(int x) {
        return first[x];
    }

    /**
     * Column x's nearest obstacle row to row y, the one above on a tie, given the column's last run
     * that starts at or above y.
     *
     * @param run that run's index
     * @return the row in the low 32 bits (as an int), its squared distance in the high ones
     */
    long nearestInColumn(int run, int y) {
        if (end[run] >= y) {
            return y;
        }
        long up = y - end[run];
        long down = start[run + 1] - y;   // the last run reaches the last row, so a next one exists here
        // The squared distance is kept in an int, as the field's sweep down the column keeps it.
        long upD2 = StrictMath.min(up * up, Integer.MAX_VALUE);
        return down * down < upD2 ? (down * down) << 32 | (y + down) : upD2 << 32 | (y - up);
    }

    /** @return the index of the run after {@code run} if it starts at or above row y, else {@code run} */
    int advance(int x, int run, int y) {
        while (run + 1 < first[x + 1] && start[run + 1] <= y) {
            run++;
        }
        return run;
    }

    /** @return column x's last run that starts at or above row y (row 0 is padding, so one does) */
    private int runAt(int x, int y) {
        int lo = first[x];
        int hi = first[x + 1] - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (start[mid] <= y) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo;
    }

    /**
     * The nearest obstacle cell of padded cell (px, py), as the field's two sweeps find it: the least
     * squared distance between centres; on a tie, the leftmost column, and in it the row above.
     * Works outward column by column until no farther column can come as near: costs about twice the
     * distance in columns, so the field asks only for cells it does not keep (far from every obstacle).
     *
     * @return {@code row << 16 | col}, padded
     */
    int nearest(int px, int py) {
        long best = Long.MAX_VALUE;
        int bestCol = -1;
        int bestRow = -1;
        for (int k = 0; (long) k * k <= best; k++) {
            int left = px - k;
            int right = px + k;
            if (left < 0 && right >= pw) {
                break;
            }
            for (int q = left; q <= right; q += StrictMath.max(1, 2 * k)) {
                if (q < 0 || q >= pw) {
                    continue;
                }
                long col = nearestInColumn(runAt(q, py), py);
                long d = (long) k * k + (col >>> 32);
                if (d < best || d == best && q < bestCol) {
                    best = d;
                    bestCol = q;
                    bestRow = (int) col;
                }
            }
        }
        return bestRow << 16 | bestCol;
    }
}
