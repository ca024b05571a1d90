package org.kheperasim.sim.arena;

import java.util.Arrays;

/**
 * Which cells of an {@link OccupancyGrid} are open floor, one bit a cell, in tiles of
 * {@value #TILE} x {@value #TILE} cells: bit {@code (row % 32) * 32 + col % 32} of tile
 * {@code (row / 32) * tilesAcross + col / 32}, 64 to a word. A robot's record of the cells it covered
 * keeps the same layout, so the floor it covered is counted a word at a time. The grid keeps it up to
 * date with every cell it writes. Not thread-safe; shared by a copy of the grid until either writes.
 */
public final class FloorBits {
    /** Cells along a tile's side, and its power of two. */
    public static final int TILE = 32;
    public static final int TILE_SHIFT = 5;
    /** Words a tile. */
    public static final int WORDS = TILE * TILE / 64;

    private final int tilesAcross;
    private long[] bits;

    /** All floor: every bit set (those past the grid's edge too; no cell there is ever counted). */
    FloorBits(int cols, int rows) {
        this.tilesAcross = (cols + TILE - 1) >> TILE_SHIFT;
        int tilesDown = (rows + TILE - 1) >> TILE_SHIFT;
        this.bits = new long[Math.multiplyExact(tilesAcross * WORDS, tilesDown)];
        Arrays.fill(bits, -1L);
    }

    private FloorBits(FloorBits from) {
        this.tilesAcross = from.tilesAcross;
        this.bits = from.bits.clone();
    }

    /** @return a copy to write to */
    FloorBits copy() {
        return new FloorBits(this);
    }

    /** Every cell floor again. */
    void fill() {
        Arrays.fill(bits, -1L);
    }

    /** Cell (col, row), inside the grid, is floor or not. */
    void set(int col, int row, boolean floor) {
        int bit = ((row & (TILE - 1)) << TILE_SHIFT) | (col & (TILE - 1));
        int w = ((row >> TILE_SHIFT) * tilesAcross + (col >> TILE_SHIFT)) * WORDS + (bit >> 6);
        if (floor) {
            bits[w] |= 1L << bit;
        } else {
            bits[w] &= ~(1L << bit);
        }
    }

    /**
     * @param tileCol a tile's column ({@code col / 32})
     * @param tileRow its row
     * @param word 0 to {@link #WORDS} - 1
     * @return the floor bits of that word of the tile
     */
    public long word(int tileCol, int tileRow, int word) {
        return bits[(tileRow * tilesAcross + tileCol) * WORDS + word];
    }
}
