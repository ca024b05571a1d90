package org.kheperasim.sim.arena.wsu;

import java.util.Arrays;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.DistanceField;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.engine.robot.RobotTypes;

/**
 * Where a robot can start: its body (a disc of the Khepera I's radius, the robot of the WSU worlds) must not overlap a
 * wall or lamp cell of the occupancy grid, nor the edge, the test {@code ArenaFormat} makes of every
 * robot line. Caps may touch it: it pushes them.
 */
final class RobotPlacement {
    /** Extra clearance, mm, so that rounding the pose for the text file cannot make it overlap. */
    private static final double MARGIN_MM = 0.01;

    private final OccupancyGrid grid;
    private final double radius;

    private RobotPlacement(OccupancyGrid grid, double radius) {
        this.grid = grid;
        this.radius = radius;
    }

    /**
     * @param arena an arena whose walls and lamps are final (its robot poses are not looked at)
     * @param x     the wanted centre, mm
     * @param y     the wanted centre, mm
     * @return {@code {x, y}} when the robot fits there, else the nearest point where it fits (a cell
     *     centre, mm), or null when it fits nowhere
     */
    static double[] nearestFree(Arena arena, double x, double y) {
        RobotPlacement p = new RobotPlacement(OccupancyGrid.of(arena),
                RobotTypes.KHEPERA1.body().radiusMm() + MARGIN_MM);
        return p.search(x, y);
    }

    private double[] search(double x, double y) {
        if (fits(x, y)) {
            return new double[] {x, y};
        }
        DistanceField field = DistanceField.of(grid);
        double cell = grid.cellSize();
        int cols = grid.cols();
        int rows = grid.rows();
        long[] candidates = new long[cols * rows];
        int n = 0;
        int c0 = grid.col(x);
        int r0 = grid.row(y);
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                // The field is within about a cell of the true clearance: a cheap first cut.
                if (field.clearance(grid.cellCentreX(c), grid.cellCentreY(r)) >= radius - 2 * cell) {
                    long d2 = (long) (c - c0) * (c - c0) + (long) (r - r0) * (r - r0);
                    candidates[n++] = (d2 << 32) | ((long) r << 16) | c;
                }
            }
        }
        long[] sorted = Arrays.copyOf(candidates, n);
        Arrays.sort(sorted);
        for (long key : sorted) {
            int r = (int) ((key >>> 16) & 0xFFFF);
            int c = (int) (key & 0xFFFF);
            double cx = grid.cellCentreX(c);
            double cy = grid.cellCentreY(r);
            if (fits(cx, cy)) {
                return new double[] {cx, cy};
            }
        }
        return null;
    }

    /** Whether no wall or lamp cell, and no place off the grid, lies within the radius of (x, y). */
    private boolean fits(double x, double y) {
        double cell = grid.cellSize();
        for (int r = grid.row(y - radius); r <= grid.row(y + radius); r++) {
            for (int c = grid.col(x - radius); c <= grid.col(x + radius); c++) {
                int id = grid.id(c, r);
                if (id != OccupancyGrid.WALL && id != OccupancyGrid.LIGHT) {
                    continue;
                }
                double dx = Math.max(0, Math.max(c * cell - x, x - (c + 1) * cell));
                double dy = Math.max(0, Math.max(r * cell - y, y - (r + 1) * cell));
                if (dx * dx + dy * dy < radius * radius) {
                    return false;
                }
            }
        }
        return true;
    }
}
