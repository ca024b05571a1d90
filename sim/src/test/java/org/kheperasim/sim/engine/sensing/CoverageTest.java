package org.kheperasim.sim.engine.sensing;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.space.World;

/**
 * The floor a robot has covered is the union of its body's footprints around every centre cell of
 * its path, however often it passes the same cells (the coverage skips centre cells met before).
 */
class CoverageTest {
    private static final World WORLD = new World(ArenaFormat.parse(
            "khepera-arena 1\nname t\nsize 600 600\nrobot 100 100 0\nwall 200 200 260 400 20\n", "t.arena"));
    /** A swarm-sized floor: its coverage bitmap spans several blocks of tiles (624 mm each way). */
    private static final World LARGE = new World(ArenaFormat.parse(
            "khepera-arena 1\nname big\nsize 4000 3000\nrobot 100 100 0\nwall 1900 700 1960 2300 20\n", "big.arena"));

    @Test
    void aRobotGoingRoundTheSameLoopAgainCoversNothingMore() {
        Coverage c = new Coverage(WORLD, 100, 100, RobotTypes.KHEPERA1.body().radiusMm());
        double[][] path = {{100, 100}, {500, 120}, {480, 500}, {90, 480}, {100, 100}};
        for (double[] p : path) {
            c.mark(p[0], p[1]);
        }
        double once = c.visitedPercent();
        for (int lap = 0; lap < 3; lap++) {
            for (double[] p : path) {
                c.mark(p[0], p[1]);
            }
        }
        assertEquals(once, c.visitedPercent(), 0.0);
        assertEquals(reference(WORLD, path), once, 1e-9);
    }

    /** Random walks that come back on themselves, some running off the arena's edge. */
    @Test
    void coverageIsTheUnionOfTheFootprintsAlongThePath() {
        for (long seed = 0; seed < 60; seed++) {
            java.util.SplittableRandom random = new java.util.SplittableRandom(seed);
            assertEquals(reference(WORLD, walk(random, 600, 600)), covered(WORLD, walk(new java.util.SplittableRandom(seed), 600, 600)), 1e-9,
                    "seed " + seed);
        }
    }

    /** The same on a floor of several blocks of tiles, the walks crossing blocks and the edges. */
    @Test
    void onALargeFloorToo() {
        for (long seed = 0; seed < 30; seed++) {
            java.util.SplittableRandom random = new java.util.SplittableRandom(seed);
            assertEquals(reference(LARGE, walk(random, 4000, 3000)), covered(LARGE, walk(new java.util.SplittableRandom(seed), 4000, 3000)), 1e-9,
                    "seed " + seed);
        }
    }

    private static double covered(World world, double[][] path) {
        Coverage c = new Coverage(world, path[0][0], path[0][1], RobotTypes.KHEPERA1.body().radiusMm());
        for (double[] p : path) {
            c.mark(p[0], p[1]);
        }
        return c.visitedPercent();
    }

    /** A walk over a floor of width x height mm, running up to 40 mm off its edges; long moves a third of the width. */
    private static double[][] walk(java.util.SplittableRandom random, double width, double height) {
        int steps = 1 + random.nextInt(120);
        double[][] path = new double[steps][];
        double x = 20 + random.nextDouble(width - 40);
        double y = 20 + random.nextDouble(height - 40);
        for (int k = 0; k < steps; k++) {
            // Short and long moves, sometimes back to an earlier point.
            if (k > 2 && random.nextInt(5) == 0) {
                double[] back = path[random.nextInt(k)];
                x = back[0];
                y = back[1];
            } else {
                double reach = random.nextInt(4) == 0 ? width / 3 : 12;
                x = StrictMath.min(width + 40, StrictMath.max(-40, x + random.nextDouble(-reach, reach)));
                y = StrictMath.min(height + 40, StrictMath.max(-40, y + random.nextDouble(-reach, reach)));
            }
            path[k] = new double[] {x, y};
        }
        return path;
    }

    /**
     * The covered floor written from the model's words: the chain of neighbouring centre cells from
     * each marked point to the next (a diagonal step while neither axis leads by more than two to
     * one), every cell of the grid whose centre lies within the body's radius of a chain cell's
     * centre, counted where it is floor.
     */
    private static double reference(World world, double[][] path) {
        OccupancyGrid g = world.grid();
        boolean[] covered = new boolean[g.cols() * g.rows()];
        int reach = (int) StrictMath.ceil(RobotTypes.KHEPERA1.body().radiusMm() / OccupancyGrid.CELL_MM);
        int col = g.col(path[0][0]);
        int row = g.row(path[0][1]);
        cover(covered, g, col, row, reach);
        for (double[] p : path) {
            int tc = g.col(p[0]);
            int tr = g.row(p[1]);
            while (col != tc || row != tr) {
                int ac = StrictMath.abs(tc - col);
                int ar = StrictMath.abs(tr - row);
                col += ac > 2 * ar ? Integer.signum(tc - col) : ar > 2 * ac ? 0 : Integer.signum(tc - col);
                row += ar > 2 * ac ? Integer.signum(tr - row) : ac > 2 * ar ? 0 : Integer.signum(tr - row);
                cover(covered, g, col, row, reach);
            }
        }
        int free = 0;
        int hit = 0;
        for (int r = 0; r < g.rows(); r++) {
            for (int c = 0; c < g.cols(); c++) {
                if (g.id(c, r) == OccupancyGrid.FLOOR) {
                    free++;
                    hit += covered[r * g.cols() + c] ? 1 : 0;
                }
            }
        }
        return 100.0 * hit / free;
    }

    private static void cover(boolean[] covered, OccupancyGrid g, int col, int row, int reach) {
        for (int dr = -reach; dr <= reach; dr++) {
            for (int dc = -reach; dc <= reach; dc++) {
                int c = col + dc;
                int r = row + dr;
                if (c >= 0 && r >= 0 && c < g.cols() && r < g.rows()
                        && StrictMath.hypot(dc * OccupancyGrid.CELL_MM, dr * OccupancyGrid.CELL_MM) <= RobotTypes.KHEPERA1.body().radiusMm()) {
                    covered[r * g.cols() + c] = true;
                }
            }
        }
    }
}
