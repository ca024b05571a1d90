package org.kheperasim.sim.arena;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.sim.arena.OccupancyGrid.CELL_MM;
import static org.kheperasim.sim.arena.OccupancyGrid.FLOOR;
import static org.kheperasim.sim.arena.OccupancyGrid.WALL;

import java.time.Duration;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class DistanceFieldTest {

    private static final double EPS = 1e-9;

    private static OccupancyGrid randomGrid(long seed, int cols, int rows, double density) {
        SplittableRandom rnd = new SplittableRandom(seed);
        OccupancyGrid g = new OccupancyGrid(cols, rows);
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                if (rnd.nextDouble() < density) {
                    g.set(c, r, rnd.nextBoolean() ? WALL : 3 + rnd.nextInt(5));
                }
            }
        }
        return g;
    }

    /** Walls and lights are obstacles to the field; caps move and are not. */
    private static boolean fixed(int id) {
        return id == WALL || id == OccupancyGrid.LIGHT;
    }

    /** Squared centre distance, in cells, from a cell to the nearest obstacle cell (the ring outside counts). */
    private static long bruteDist2(OccupancyGrid g, int col, int row) {
        long best = Long.MAX_VALUE;
        for (int r = -1; r <= g.rows(); r++) {
            for (int c = -1; c <= g.cols(); c++) {
                if (fixed(g.id(c, r))) {
                    long d = (long) (c - col) * (c - col) + (long) (r - row) * (r - row);
                    best = Math.min(best, d);
                }
            }
        }
        return best;
    }

    /** True clearance of a point: distance to the nearest obstacle square, or to the outside. */
    private static double bruteClearance(OccupancyGrid g, double x, double y) {
        double best = Math.min(Math.min(x, y), Math.min(g.cols() * CELL_MM - x, g.rows() * CELL_MM - y));
        for (int r = 0; r < g.rows(); r++) {
            for (int c = 0; c < g.cols(); c++) {
                if (fixed(g.id(c, r))) {
                    best = Math.min(best, toSquare(x, y, c, r));
                }
            }
        }
        return best;
    }

    private static double toSquare(double x, double y, int c, int r) {
        double dx = Math.max(0, Math.max(c * CELL_MM - x, x - (c + 1) * CELL_MM));
        double dy = Math.max(0, Math.max(r * CELL_MM - y, y - (r + 1) * CELL_MM));
        return Math.sqrt(dx * dx + dy * dy);
    }

    @ParameterizedTest
    @ValueSource(doubles = {0, 0.002, 0.05, 0.3, 0.9, 1})
    void matchesBruteForceOnRandomGrids(double density) {
        OccupancyGrid g = randomGrid(7919 + (long) (density * 1000), 37, 23, density);
        DistanceField df = DistanceField.of(g);
        for (int r = 0; r < g.rows(); r++) {
            for (int c = 0; c < g.cols(); c++) {
                double x = g.cellCentreX(c);
                double y = g.cellCentreY(r);
                double nx = df.nearestObstacleX(x, y);
                double ny = df.nearestObstacleY(x, y);
                int nc = g.col(nx);
                int nr = g.row(ny);
                assertTrue(fixed(g.id(nc, nr)), "nearest of " + c + "," + r + " is an obstacle");
                long d2 = (long) (nc - c) * (nc - c) + (long) (nr - r) * (nr - r);
                assertEquals(bruteDist2(g, c, r), d2, "cell " + c + "," + r);
                assertEquals(toSquare(x, y, nc, nr), df.clearance(x, y), EPS);
            }
        }
    }

    /**
     * Far from every wall the field keeps no tiles and works a cell's nearest obstacle out when asked:
     * it is the very cell the sweeps find, the nearest by centres, on a tie the leftmost column and in
     * it the upper row (checked against every obstacle cell, in kept tiles and in the others).
     */
    @Test
    void cellsOfTilesNotKeptHaveTheNearestObstacleTheSweepsFind() {
        OccupancyGrid g = new OccupancyGrid(430, 400);
        g.set(400, 380, WALL);
        for (int c = 100; c < 140; c++) {
            g.set(c, 20, WALL);   // a wall, and ties along it
        }
        DistanceField df = DistanceField.of(g);
        int[] kept = df.tilesKept();
        assertTrue(kept[0] > 0 && kept[0] < kept[1], "some tiles kept, some not: " + kept[0] + " of " + kept[1]);
        java.util.List<int[]> obstacles = new java.util.ArrayList<>();
        for (int r = -1; r <= g.rows(); r++) {
            for (int c = -1; c <= g.cols(); c++) {
                if (fixed(g.id(c, r))) {
                    obstacles.add(new int[] {c, r});
                }
            }
        }
        for (int r = 0; r < g.rows(); r++) {
            for (int c = 0; c < g.cols(); c++) {
                long best = Long.MAX_VALUE;
                int[] at = null;
                for (int[] o : obstacles) {
                    long d = (long) (o[0] - c) * (o[0] - c) + (long) (o[1] - r) * (o[1] - r);
                    if (d < best || d == best && (o[0] < at[0] || o[0] == at[0] && o[1] < at[1])) {
                        best = d;
                        at = o;
                    }
                }
                double x = g.cellCentreX(c);
                double y = g.cellCentreY(r);
                assertEquals(g.cellCentreX(at[0]), df.nearestObstacleX(x, y), EPS, "cell " + c + "," + r);
                assertEquals(g.cellCentreY(at[1]), df.nearestObstacleY(x, y), EPS, "cell " + c + "," + r);
            }
        }
    }

    /** Open floor keeps only the tiles near its edges: a 6.3 m square (a swarm of 1,000) keeps under a quarter. */
    @Test
    void openFloorKeepsOnlyTheTilesNearItsWalls() {
        DistanceField df = DistanceField.of(new OccupancyGrid(2600, 2600));
        int[] kept = df.tilesKept();
        assertTrue(kept[0] * 4 < kept[1], kept[0] + " of " + kept[1] + " tiles kept");
        double mid = 1300.5 * CELL_MM;
        assertEquals(1299.5 * CELL_MM, df.clearance(mid, mid), EPS);
        assertEquals(255 * CELL_MM / 4, df.clearanceBelow(mid, mid), EPS);
    }

    /** A column longer than 46,340 cells: a distance's square there passes an int's range. */
    @Test
    void aVeryLongColumnFindsItsNearestObstacle() {
        OccupancyGrid g = new OccupancyGrid(3, 46_400);
        DistanceField df = DistanceField.of(g);
        for (int r : new int[] {0, 1, 20_000, 23_199, 23_200, 46_398, 46_399}) {
            double x = g.cellCentreX(1);
            double y = g.cellCentreY(r);
            int nc = g.col(df.nearestObstacleX(x, y));
            int nr = g.row(df.nearestObstacleY(x, y));
            long d2 = (long) (nc - 1) * (nc - 1) + (long) (nr - r) * (nr - r);
            assertEquals(bruteDist2(g, 1, r), d2, "row " + r);
            assertTrue(df.clearanceBelow(x, y) <= df.clearance(x, y), "row " + r);
        }
    }

    @Test
    void clearanceOfAnyPointIsWithinACoupleOfCellsOfTheTruth() {
        OccupancyGrid g = randomGrid(42, 40, 30, 0.04);
        DistanceField df = DistanceField.of(g);
        SplittableRandom rnd = new SplittableRandom(43);
        for (int i = 0; i < 2000; i++) {
            double x = rnd.nextDouble() * g.cols() * CELL_MM;
            double y = rnd.nextDouble() * g.rows() * CELL_MM;
            double truth = bruteClearance(g, x, y);
            double got = df.clearance(x, y);
            assertTrue(got >= truth - EPS && got <= truth + 2.2 * CELL_MM,
                    "at (" + x + ", " + y + "): " + got + " vs " + truth);
        }
    }

    @Test
    void obstaclesAndTheOutsideHaveNoClearance() {
        OccupancyGrid g = new OccupancyGrid(10, 10);
        g.set(4, 4, WALL);
        DistanceField df = DistanceField.of(g);
        assertEquals(0, df.clearance(4.5 * CELL_MM, 4.2 * CELL_MM));
        assertEquals(0, df.clearance(-1, 5));
        assertEquals(0, df.clearance(5, 10 * CELL_MM + 1));
        assertEquals(-0.5 * CELL_MM, df.nearestObstacleX(-0.1, 5), EPS);
        // Next to the edge the nearest obstacle is the padding just outside.
        assertEquals(0.3 * CELL_MM, df.clearance(0.3 * CELL_MM, 8.5 * CELL_MM), EPS);
        assertEquals(-0.5 * CELL_MM, df.nearestObstacleX(0.3 * CELL_MM, 8.5 * CELL_MM), EPS);
    }

    @Test
    void labCentreIsAboutHalfTheArenaFromTheWalls() {
        DistanceField df = DistanceField.of(OccupancyGrid.of(ArenaFormat.loadBundled("lab")));
        assertEquals(609.6 - 8, df.clearance(609.7, 609.7), 1.5 * CELL_MM);
        assertEquals(50 - 8, df.clearance(50.1, 609.7), 1.5 * CELL_MM);
    }

    @Test
    void recomputeFollowsGridEdits() {
        OccupancyGrid g = new OccupancyGrid(50, 50);
        DistanceField df = DistanceField.of(g);
        double x = 25.5 * CELL_MM;
        double y = 25.5 * CELL_MM;
        assertEquals(24.5 * CELL_MM, df.clearance(x, y), EPS); // to the grid's right edge
        g.set(30, 25, OccupancyGrid.FIRST_CAP);
        df.recompute();
        assertEquals(24.5 * CELL_MM, df.clearance(x, y), EPS); // caps are not in the field
        g.set(30, 25, WALL);
        assertEquals(24.5 * CELL_MM, df.clearance(x, y), EPS); // a snapshot until recomputed
        df.recompute();
        assertEquals(4.5 * CELL_MM, df.clearance(x, y), EPS);
        assertEquals(30.5 * CELL_MM, df.nearestObstacleX(x, y), EPS);
        assertEquals(25.5 * CELL_MM, df.nearestObstacleY(x, y), EPS);
        g.set(30, 25, FLOOR);
        df.recompute();
        assertEquals(24.5 * CELL_MM, df.clearance(x, y), EPS);
    }

    @Test
    void labFieldIsQuick() {
        OccupancyGrid g = OccupancyGrid.of(ArenaFormat.loadBundled("maze"));
        DistanceField df = DistanceField.of(g);
        long start = System.nanoTime();
        for (int i = 0; i < 10; i++) {
            df.recompute();
        }
        Duration each = Duration.ofNanos((System.nanoTime() - start) / 10);
        // A sanity bound only; a warm JVM takes a few milliseconds.
        assertTrue(each.compareTo(Duration.ofSeconds(2)) < 0, "recompute took " + each);
    }
}
