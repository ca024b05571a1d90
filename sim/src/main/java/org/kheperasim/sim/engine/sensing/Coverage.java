package org.kheperasim.sim.engine.sensing;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.kheperasim.sim.arena.FloorBits;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.Region;
import org.kheperasim.sim.engine.space.World;

/**
 * What a robot has visited: the floor cells its body has covered, and the named regions its centre
 * has entered (with the time of the first entry).
 *
 * <p>Cells are marked along the centre's path as a chain of neighbouring cells, from one marking
 * point to the next (the poll samples), each step adding the body's leading edge; the bitmap is
 * kept in tiles allocated on first visit, so a robot that stays in one room costs a few kilobytes.
 * The covered cells are the union of the footprints around every centre cell of the chain, so a
 * centre cell met again adds nothing: a second bitmap of the centre cells already met lets the
 * chain pass them without stamping (a robot circling a room stamps almost nothing after a while).
 * Regions are checked at the end of every move; the engine steps tick by tick near a region not
 * yet entered, so the entry time is the same however it steps.
 */
public final class Coverage {
    private static final int TILE_SHIFT = FloorBits.TILE_SHIFT;
    private static final int TILE = FloorBits.TILE;
    /** The body's footprint in cells, as (dc, dr) pairs, and its leading edge for each of the 8 steps. */
    private final int[] footprint;
    private final int[][] edges;
    /** No footprint cell is farther than this from the centre's cell along either axis. */
    private final int reach;

    private final World world;
    private final OccupancyGrid grid;
    private final int tilesAcross;
    private final Tiles tiles;
    /** The centre cells the chain has met, in the same tiles: their whole footprints are covered. */
    private final Tiles centres;
    private int lastCol = Integer.MIN_VALUE;
    private int lastRow;
    private List<Region> regions;
    private long[] entered;
    /** How many regions are not entered yet: once all are, no move needs to look at them. */
    private int unentered;
    /**
     * Where {@link #freeTravelMm} last looked, and what it found (negative: nothing to go by): a centre
     * nearer that place than that, less {@link #ANCHOR_MARGIN_MM} for rounding, is in no region not entered.
     */
    private double anchorX;
    private double anchorY;
    private double anchorFree = -1;
    private static final double ANCHOR_MARGIN_MM = 1e-6;

    /**
     * @param world the world
     * @param startX where the robot starts, mm: the regions it starts in are entered at time 0
     * @param startY where the robot starts, mm
     */
    /**
     * @param world the world
     * @param startX the start, mm
     * @param startY the start, mm
     * @param radius the body's radius, mm
     */
    public Coverage(World world, double startX, double startY, double radius) {
        Shape shape = SHAPES.computeIfAbsent(radius, Shape::of);
        this.footprint = shape.footprint();
        this.edges = shape.edges();
        this.reach = shape.reach();
        this.world = world;
        this.grid = world.grid();
        this.tilesAcross = (grid.cols() + TILE - 1) >> TILE_SHIFT;
        this.tiles = new Tiles(tilesAcross);
        this.centres = new Tiles(tilesAcross);
        this.regions = world.arena().regions();
        this.entered = new long[regions.size()];
        Arrays.fill(entered, -1);
        unentered = entered.length;
        regionsAt(startX, startY, 0);
    }

    /** Mark the cells covered on the way from the last marked position to (x, y). */
    void mark(double x, double y) {
        int col = grid.col(x);
        int row = grid.row(y);
        if (lastCol == Integer.MIN_VALUE) {
            lastCol = col;
            lastRow = row;
            if (firstVisit(col, row)) {
                stamp(col, row, footprint);
            }
            return;
        }
        // Walk the chain of neighbouring cells from the last centre cell to this one.
        while (col != lastCol || row != lastRow) {
            int dc = Integer.signum(col - lastCol);
            int dr = Integer.signum(row - lastRow);
            int ac = StrictMath.abs(col - lastCol);
            int ar = StrictMath.abs(row - lastRow);
            if (ac > 2 * ar) {
                dr = 0;
            } else if (ar > 2 * ac) {
                dc = 0;
            }
            lastCol += dc;
            lastRow += dr;
            // The last centre cell's footprint is covered: a new one adds its leading edge only.
            if (firstVisit(lastCol, lastRow)) {
                stamp(lastCol, lastRow, edges[(dr + 1) * 3 + (dc + 1)]);
            }
        }
    }

    /** Note the centre cell (col, row): true the first time (its footprint is then still to stamp). */
    private boolean firstVisit(int col, int row) {
        if (col < 0 || row < 0 || col >= grid.cols() || row >= grid.rows()) {
            return true;
        }
        long[] tile = centres.make(col >> TILE_SHIFT, row >> TILE_SHIFT);
        int bit = ((row & (TILE - 1)) << TILE_SHIFT) | (col & (TILE - 1));
        long mask = 1L << bit;
        if ((tile[bit >> 6] & mask) != 0) {
            return false;
        }
        tile[bit >> 6] |= mask;
        return true;
    }

    private void stamp(int col, int row, int[] offsets) {
        int cols = grid.cols();
        int rows = grid.rows();
        // Well inside the grid (the usual case) no cell needs its own bounds check.
        boolean inside = col >= reach && row >= reach && col + reach < cols && row + reach < rows;
        int lastT = -1;
        long[] tile = null;
        for (int k = 0; k < offsets.length; k += 2) {
            int c = col + offsets[k];
            int r = row + offsets[k + 1];
            if (inside || c >= 0 && r >= 0 && c < cols && r < rows) {
                int t = (r >> TILE_SHIFT) * tilesAcross + (c >> TILE_SHIFT);
                if (t != lastT) {
                    tile = tiles.make(c >> TILE_SHIFT, r >> TILE_SHIFT);
                    lastT = t;
                }
                int bit = ((r & (TILE - 1)) << TILE_SHIFT) | (c & (TILE - 1));
                tile[bit >> 6] |= 1L << bit;
            }
        }
    }

    /** The centre is at (x, y) at the end of a move at {@code timeNanos}: note the regions it is in. */
    public void regionsAt(double x, double y, long timeNanos) {
        if (unentered == 0) {
            return;
        }
        if (anchorFree > ANCHOR_MARGIN_MM) {
            // Nearer the last place freeTravelMm looked from than the nearest region not yet entered was:
            // still outside them all.
            double dx = x - anchorX;
            double dy = y - anchorY;
            double within = anchorFree - ANCHOR_MARGIN_MM;
            if (dx * dx + dy * dy < within * within) {
                return;
            }
        }
        for (int k = 0; k < entered.length; k++) {
            if (entered[k] < 0 && regions.get(k).contains(x, y)) {
                entered[k] = timeNanos;
                unentered--;
                anchorFree = -1;
            }
        }
    }

    /** @return how far the centre can travel from (x, y) without entering a region not yet entered, mm */
    public double freeTravelMm(double x, double y) {
        double best = Double.POSITIVE_INFINITY;
        if (unentered == 0) {
            return best;
        }
        for (int k = 0; k < entered.length; k++) {
            if (entered[k] < 0) {
                Region g = regions.get(k);
                double dx = StrictMath.max(0, StrictMath.max(g.x1() - x, x - g.x2()));
                double dy = StrictMath.max(0, StrictMath.max(g.y1() - y, y - g.y2()));
                best = StrictMath.min(best, StrictMath.sqrt(dx * dx + dy * dy));
            }
        }
        anchorX = x;
        anchorY = y;
        anchorFree = best;
        return best;
    }

    /** The arena was edited: take its regions, keeping the entry times of those that kept their names. */
    public void arenaEdited() {
        List<Region> edited = world.arena().regions();
        long[] next = new long[edited.size()];
        Arrays.fill(next, -1);
        for (int k = 0; k < edited.size(); k++) {
            for (int j = 0; j < regions.size(); j++) {
                if (regions.get(j).name().equals(edited.get(k).name())) {
                    next[k] = entered[j];
                }
            }
        }
        regions = edited;
        entered = next;
        anchorFree = -1;
        unentered = 0;
        for (long t : next) {
            unentered += t < 0 ? 1 : 0;
        }
    }

    /** @return percentage of the arena's floor cells (as the arena is now) the body has covered */
    public double visitedPercent() {
        if (world.freeCells() == 0) {
            return 0;
        }
        // The floor bits share the tiles' layout: a word's covered floor cells are the bits both have.
        return 100.0 * tiles.countFloor(grid.floorBits()) / world.freeCells();
    }

    /** @return the regions entered, with the first entry's simulated time in seconds, in arena order */
    public Map<String, Double> regionsEntered() {
        Map<String, Double> out = new LinkedHashMap<>();
        for (int k = 0; k < entered.length; k++) {
            if (entered[k] >= 0) {
                out.put(regions.get(k).name(), entered[k] / 1e9);
            }
        }
        return out;
    }

    /**
     * A bitmap's tiles, allocated on first use, in blocks of 8 x 8 tiles, also allocated on first use
     * and found by their index in a map of the blocks made: a robot pays for the blocks it has been in,
     * not for the floor (a swarm of 10,000 robots has 33 x 33 blocks a side, which as a directory would
     * cost every robot 9 KB). The block asked for last is kept at hand: a stamp stays in one block.
     */
    private static final class Tiles {
        private static final int BLOCK_SHIFT = 3;
        private static final int BLOCK = 1 << BLOCK_SHIFT;
        private final int blocksAcross;
        private final Map<Integer, long[][]> blocks = new java.util.HashMap<>();
        private long[][] lastBlock;
        private int lastKey = -1;

        Tiles(int across) {
            this.blocksAcross = (across + BLOCK - 1) >> BLOCK_SHIFT;
        }

        /** @return tile (tc, tr), made empty if it was not there */
        long[] make(int tc, int tr) {
            int b = (tr >> BLOCK_SHIFT) * blocksAcross + (tc >> BLOCK_SHIFT);
            if (b != lastKey) {
                lastBlock = blocks.computeIfAbsent(b, k -> new long[BLOCK * BLOCK][]);
                lastKey = b;
            }
            int k = ((tr & (BLOCK - 1)) << BLOCK_SHIFT) | (tc & (BLOCK - 1));
            long[] tile = lastBlock[k];
            if (tile == null) {
                tile = new long[TILE * TILE / 64];
                lastBlock[k] = tile;
            }
            return tile;
        }

        /** @return how many of the cells marked are floor in {@code floor} (which has the tiles' layout) */
        int countFloor(FloorBits floor) {
            int count = 0;
            for (Map.Entry<Integer, long[][]> e : blocks.entrySet()) {
                int tc0 = (e.getKey() % blocksAcross) << BLOCK_SHIFT;
                int tr0 = (e.getKey() / blocksAcross) << BLOCK_SHIFT;
                long[][] block = e.getValue();
                for (int k = 0; k < block.length; k++) {
                    long[] tile = block[k];
                    for (int w = 0; tile != null && w < tile.length; w++) {
                        int tc = tc0 + (k & (BLOCK - 1));
                        int tr = tr0 + (k >> BLOCK_SHIFT);
                        count += Long.bitCount(tile[w] & floor.word(tc, tr, w));
                    }
                }
            }
            return count;
        }
    }

    /** A body's footprint, its leading edges and its reach (never written after they are made). */
    private record Shape(int[] footprint, int[][] edges, int reach) {
        static Shape of(double radius) {
            int[] disc = Coverage.footprint(OccupancyGrid.CELL_MM, radius);
            return new Shape(disc, Coverage.edges(disc), Coverage.reach(disc));
        }
    }

    /** The shapes made so far, by body radius: the same for every run of robots of that size. */
    private static final Map<Double, Shape> SHAPES = new java.util.concurrent.ConcurrentHashMap<>();

    private static int[] footprint(double cell, double radius) {
        int reach = (int) StrictMath.ceil(radius / cell);
        int[] tmp = new int[(2 * reach + 1) * (2 * reach + 1) * 2];
        int n = 0;
        for (int dr = -reach; dr <= reach; dr++) {
            for (int dc = -reach; dc <= reach; dc++) {
                if (StrictMath.hypot(dc * cell, dr * cell) <= radius) {
                    tmp[n++] = dc;
                    tmp[n++] = dr;
                }
            }
        }
        return Arrays.copyOf(tmp, n);
    }

    private static int reach(int[] cells) {
        int reach = 0;
        for (int v : cells) {
            reach = StrictMath.max(reach, StrictMath.abs(v));
        }
        return reach;
    }

    /** For each step (dc, dr) to a neighbouring cell: the footprint's cells not covered before the step. */
    private static int[][] edges(int[] disc) {
        int reach = 0;
        for (int v : disc) {
            reach = StrictMath.max(reach, StrictMath.abs(v));
        }
        int side = 2 * reach + 3;
        boolean[] inDisc = new boolean[side * side];
        for (int k = 0; k < disc.length; k += 2) {
            inDisc[(disc[k + 1] + reach + 1) * side + disc[k] + reach + 1] = true;
        }
        int[][] out = new int[9][];
        for (int dr = -1; dr <= 1; dr++) {
            for (int dc = -1; dc <= 1; dc++) {
                int[] edge = new int[disc.length];
                int n = 0;
                for (int k = 0; k < disc.length; k += 2) {
                    int bc = disc[k] + dc + reach + 1;
                    int br = disc[k + 1] + dr + reach + 1;
                    if (!inDisc[br * side + bc]) {
                        edge[n++] = disc[k];
                        edge[n++] = disc[k + 1];
                    }
                }
                out[(dr + 1) * 3 + (dc + 1)] = Arrays.copyOf(edge, n);
            }
        }
        return out;
    }
}
