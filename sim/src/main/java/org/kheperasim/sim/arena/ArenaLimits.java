package org.kheperasim.sim.arena;

/**
 * The largest arena the simulator reads, and the range of every quantity in an arena file. They
 * keep any file, however made, from exhausting memory or time: the floor is drawn as a grid of
 * {@link OccupancyGrid#CELL_MM} cells (2 bytes a cell; the distance field beside it keeps only the
 * tiles near walls), so the floor's area bounds the memory, and the walls' total area bounds the
 * time to draw them.
 * Documented in {@code docs/arena-format.md}; the file reader checks them and names the line.
 */
public final class ArenaLimits {

    /** Longest side of an arena, mm (30 m). */
    public static final double MAX_SIDE_MM = 30_000;
    /**
     * Largest floor, mm² (500 m², e.g. 22.4 x 22.4 m: about 84 million grid cells, 170 MB; a swarm of 10,000 robots in
     * 200 mm cells needs 400 m²).
     */
    public static final double MAX_AREA_MM2 = 500_000_000;
    /** Most robots in one arena (each runs its own controller). */
    public static final int MAX_ROBOTS = 16_384;
    /** Most walls in one arena file. */
    public static final int MAX_WALLS = 10_000;
    /** Most lamps. */
    public static final int MAX_LIGHTS = 256;
    /** Most caps. */
    public static final int MAX_CAPS = 1_000;
    /** Most regions. */
    public static final int MAX_REGIONS = 1_000;
    /** The walls' areas (length x thickness each) may add up to this many times the floor's. */
    public static final double MAX_WALL_AREA_RATIO = 4;
    /** Thickest wall, mm. */
    public static final double MAX_WALL_THICKNESS_MM = 1_000;
    /** Largest lamp body radius, mm. */
    public static final double MAX_LIGHT_RADIUS_MM = 500;
    /** Longest lamp range, mm. */
    public static final double MAX_LIGHT_RANGE_MM = 20_000;
    /** Brightest lamp, relative to the standard lamp (1). */
    public static final double MAX_LIGHT_INTENSITY = 1_000;
    /** Largest cap radius, mm (caps are redrawn on the grid whenever they move). */
    public static final double MAX_CAP_RADIUS_MM = 50;
    /** Headings and lamp directions lie within plus or minus this, degrees. */
    public static final double MAX_ANGLE_DEG = 360;
    /** Longest number in a file, characters (the canonical form of the smallest double has about 330). */
    public static final int MAX_NUMBER_CHARS = 1000;
    /** Largest arena file, bytes. */
    public static final long MAX_FILE_BYTES = 16L << 20;

    private ArenaLimits() {
    }

    /**
     * Checks an arena's size against {@link #MAX_SIDE_MM} and {@link #MAX_AREA_MM2}.
     *
     * @param width  mm, positive
     * @param height mm, positive
     * @throws IllegalArgumentException naming the size, the limit and the fix
     */
    public static void checkSize(double width, double height) {
        if (width > MAX_SIDE_MM || height > MAX_SIDE_MM) {
            throw new IllegalArgumentException("arena size " + Numbers.brief(width) + " x " + Numbers.brief(height)
                    + " mm is too large: each side may be at most " + Numbers.brief(MAX_SIDE_MM)
                    + " mm (10 m); give the size in mm");
        }
        if (width * height > MAX_AREA_MM2) {
            throw new IllegalArgumentException("arena size " + Numbers.brief(width) + " x " + Numbers.brief(height)
                    + " mm is too large: the floor may be at most " + Numbers.brief(MAX_AREA_MM2 / 1e6) + " m² ("
                    + Numbers.brief(MAX_AREA_MM2)
                    + " mm², e.g. 7000 x 7000 or 10000 x 5000); make the arena smaller");
        }
    }
}
