package org.kheperasim.sim.arena;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.sim.arena.OccupancyGrid.CELL_MM;
import static org.kheperasim.sim.arena.OccupancyGrid.FLOOR;
import static org.kheperasim.sim.arena.OccupancyGrid.LIGHT;
import static org.kheperasim.sim.arena.OccupancyGrid.WALL;

import java.util.List;
import org.junit.jupiter.api.Test;

class OccupancyGridTest {

    /**
     * The floor bits follow every write: walls and lamps drawn, caps painted and erased, cells set, a
     * repaint; and a copy's writes leave the original's bits as they were.
     */
    @Test
    void floorBitsFollowEveryWrite() {
        Arena arena = ArenaFormat.parse("khepera-arena 1\nsize 300 200\nrobot 50 50 0\nwall 0 100 200 100 8\n"
                + "light 250 150 radius 20\ncap 100 40\n", "bits");
        OccupancyGrid g = OccupancyGrid.of(arena);
        assertFloorBits(g);
        OccupancyGrid copy = g.copy();
        copy.eraseCap(0, 100, 40, 15);
        copy.paintCap(0, 60, 160, 15);
        copy.set(3, 4, WALL);
        copy.set(40, 41, FLOOR);
        assertFloorBits(copy);
        assertFloorBits(g);
        copy.repaint(arena);
        assertFloorBits(copy);
    }

    private static void assertFloorBits(OccupancyGrid g) {
        FloorBits bits = g.floorBits();
        for (int r = 0; r < g.rows(); r++) {
            for (int c = 0; c < g.cols(); c++) {
                int bit = (r % FloorBits.TILE) * FloorBits.TILE + c % FloorBits.TILE;
                long word = bits.word(c / FloorBits.TILE, r / FloorBits.TILE, bit / 64);
                assertEquals(g.id(c, r) == FLOOR, (word >>> (bit % 64) & 1) == 1, "cell " + c + "," + r);
            }
        }
    }

    private static final double EPS = 1e-9;

    private static Arena arena(double w, double h, List<Wall> walls, List<Light> lights, List<Cap> caps) {
        return new Arena("t", w, h, List.of(new Pose(w / 2, h / 2, 0)), walls, lights, caps, List.of());
    }

    /** An empty 100 x 100 grid with column 60 solid wall. */
    private static OccupancyGrid gridWithWallColumn60() {
        OccupancyGrid g = new OccupancyGrid(100, 100);
        for (int r = 0; r < 100; r++) {
            g.set(60, r, WALL);
        }
        return g;
    }

    @Test
    void labIsTheFiveHundredSquareGridOfThePaper() {
        OccupancyGrid g = OccupancyGrid.of(ArenaFormat.loadBundled("lab"));
        assertEquals(500, g.cols());
        assertEquals(500, g.rows());
        assertEquals(1219.2 / 500, g.cellSize());
        assertEquals(WALL, g.id(0, 250));
        assertEquals(WALL, g.id(499, 250));
        assertEquals(FLOOR, g.id(250, 250));
    }

    @Test
    void otherSizesScaleTheGridKeepingTheCellSize() {
        OccupancyGrid g = OccupancyGrid.of(arena(1000, 500, List.of(), List.of(), List.of()));
        assertEquals(Math.round(1000 / CELL_MM), g.cols());
        assertEquals(Math.round(500 / CELL_MM), g.rows());
    }

    @Test
    void cellCoordinates() {
        OccupancyGrid g = new OccupancyGrid(10, 20);
        assertEquals(3, g.col(3.5 * CELL_MM));
        assertEquals(-1, g.row(-0.001));
        assertEquals(2.5 * CELL_MM, g.cellCentreX(2), EPS);
        assertEquals(7.5 * CELL_MM, g.cellCentreY(7), EPS);
    }

    @Test
    void outsideTheGridIsWall() {
        OccupancyGrid g = new OccupancyGrid(10, 20);
        assertEquals(WALL, g.id(-1, 0));
        assertEquals(WALL, g.id(0, -1));
        assertEquals(WALL, g.id(10, 0));
        assertEquals(WALL, g.id(0, 20));
        assertEquals(WALL, g.idAt(-0.01, 5));
        assertEquals(WALL, g.idAt(5, 20 * CELL_MM + 0.01));
        assertEquals(FLOOR, g.idAt(5, 5));
        assertThrows(IndexOutOfBoundsException.class, () -> g.set(10, 0, WALL));
        assertThrows(IllegalArgumentException.class, () -> g.set(0, 0, -1));
    }

    @Test
    void wallCoversTheCellsWithinHalfItsThickness() {
        // Centre line on the boundary y = 100 cells, 4 cells thick: exactly rows 98..101.
        Wall w = new Wall(50 * CELL_MM, 100 * CELL_MM, 150 * CELL_MM, 100 * CELL_MM, 4 * CELL_MM);
        OccupancyGrid g = OccupancyGrid.of(arena(400, 400, List.of(w), List.of(), List.of()));
        for (int c = 50; c < 150; c++) {
            assertEquals(FLOOR, g.id(c, 97), "col " + c);
            for (int r = 98; r <= 101; r++) {
                assertEquals(WALL, g.id(c, r), "col " + c + " row " + r);
            }
            assertEquals(FLOOR, g.id(c, 102), "col " + c);
        }
        // Rounded ends: two cells past each end on the centre rows, nothing three cells past.
        assertEquals(WALL, g.id(48, 99));
        assertEquals(FLOOR, g.id(47, 99));
        assertEquals(WALL, g.id(151, 100));
        assertEquals(FLOOR, g.id(152, 100));
    }

    @Test
    void thinDiagonalWallStaysContinuous() {
        Wall w = new Wall(100, 100, 400, 250.3, 0.5);
        OccupancyGrid g = OccupancyGrid.of(arena(500, 500, List.of(w), List.of(), List.of()));
        for (int i = 0; i <= 30000; i++) {
            double t = i / 30000.0;
            double x = 100 + t * 300;
            double y = 100 + t * 150.3;
            assertEquals(WALL, g.idAt(x, y), "at t = " + t);
        }
        // A ray crossing it anywhere stops.
        RayHit hit = new RayHit();
        for (double x = 110; x < 390; x += 0.37) {
            assertTrue(g.castRay(x, 5, 0, 1, 1000, hit) < 300, "x = " + x);
            assertEquals(WALL, hit.id);
        }
    }

    @Test
    void lightIsADiscOfItsRadius() {
        double cx = 100.5 * CELL_MM;
        double cy = 80.5 * CELL_MM;
        Light light = new Light(cx, cy, 6, 400, 1, 0, 360);
        OccupancyGrid g = OccupancyGrid.of(arena(400, 400, List.of(), List.of(light), List.of()));
        int count = 0;
        for (int r = 0; r < g.rows(); r++) {
            for (int c = 0; c < g.cols(); c++) {
                double d = Math.hypot(g.cellCentreX(c) - cx, g.cellCentreY(r) - cy);
                assertEquals(d <= 6 ? LIGHT : FLOOR, g.id(c, r), "cell " + c + ", " + r);
                count += g.id(c, r) == LIGHT ? 1 : 0;
            }
        }
        assertEquals(21, count); // cell offsets with dx^2 + dy^2 <= (6 / 2.4384)^2 = 6.05
    }

    @Test
    void capsGetTheirOwnIdsAndNeverOverwriteWalls() {
        Wall w = new Wall(0, 200, 400, 200, 8);
        List<Cap> caps = List.of(new Cap(100, 100), new Cap(300, 100, 0.2), new Cap(200, 205));
        OccupancyGrid g = OccupancyGrid.of(arena(400, 400, List.of(w), List.of(), caps));
        assertEquals(3, OccupancyGrid.capId(0));
        assertEquals(OccupancyGrid.capId(0), g.idAt(100, 100));
        assertEquals(OccupancyGrid.capId(0), g.idAt(107, 100));
        assertEquals(FLOOR, g.idAt(111, 100));
        assertEquals(OccupancyGrid.capId(1), g.idAt(300, 100)); // smaller than a cell: still one cell
        assertEquals(WALL, g.idAt(200, 200));
        assertEquals(OccupancyGrid.capId(2), g.idAt(200, 212));
    }

    @Test
    void rayStopsExactlyAtAFaceOnACellBoundary() {
        OccupancyGrid g = gridWithWallColumn60();
        RayHit hit = new RayHit();
        double x = 12.345;
        double y = 50;
        double expected = 60 * CELL_MM - x;
        assertEquals(expected, g.castRay(x, y, 1, 0, 1000, hit), EPS);
        assertEquals(expected, hit.distance, EPS);
        assertEquals(WALL, hit.id);
        assertEquals(60, hit.col);
        assertEquals(g.row(y), hit.row);
        assertTrue(hit.isHit());

        // Diagonal and arbitrary directions meet the same face at (face - x) / cos.
        for (int deg = -40; deg <= 40; deg += 5) {
            double a = StrictMath.toRadians(deg);
            double d = g.castRay(x, 120, StrictMath.cos(a), StrictMath.sin(a), 1000, hit);
            assertEquals(expected / StrictMath.cos(a), d, EPS, "at " + deg + " degrees");
            assertEquals(60, hit.col);
        }
        // Coming from the other side, the face is the cell's right edge.
        double fromRight = 200;
        assertEquals(fromRight - 61 * CELL_MM, g.castRay(fromRight, 30, -1, 0, 1000, hit), EPS);
        assertEquals(60, hit.col);
    }

    @Test
    void rayRespectsMaxDistAndStopsAtTheGridEdge() {
        OccupancyGrid g = gridWithWallColumn60();
        RayHit hit = new RayHit();
        double face = 60 * CELL_MM - 10;
        assertEquals(Double.POSITIVE_INFINITY, g.castRay(10, 50, 1, 0, face - 0.001, hit));
        assertFalse(hit.isHit());
        assertEquals(FLOOR, hit.id);
        assertEquals(face, g.castRay(10, 50, 1, 0, face + 0.001, hit), EPS);

        // Nothing to the left but the edge of the world, which is wall.
        assertEquals(10, g.castRay(10, 50, -1, 0, 1000, hit), EPS);
        assertEquals(WALL, hit.id);
        assertEquals(-1, hit.col);
        double s = StrictMath.sqrt(0.5);
        assertEquals(50 / s, g.castRay(60, 50, -s, -s, 1000, hit), 1e-6);

        // Starting inside an obstacle or outside the grid: distance 0.
        assertEquals(0, g.castRay(60.5 * CELL_MM, 50, 1, 0, 1000, hit));
        assertEquals(60, hit.col);
        assertEquals(0, g.castRay(-5, 50, 1, 0, 1000, hit));
        // No direction: no hit.
        assertEquals(Double.POSITIVE_INFINITY, g.castRay(10, 50, 0, 0, Double.POSITIVE_INFINITY, hit));
    }

    @Test
    void rayFindsWallsAndLightsOffTheCellBoundariesWithinACell() {
        Arena a = arena(1000, 1000, List.of(new Wall(500, 100, 500, 900, 8)),
                List.of(new Light(300, 700, 6, 400, 1, 0, 360)), List.of());
        OccupancyGrid g = OccupancyGrid.of(a);
        RayHit hit = new RayHit();
        assertEquals(396, g.castRay(100, 400, 1, 0, 2000, hit), CELL_MM);
        assertEquals(WALL, hit.id);
        assertEquals(296, g.castRay(800, 400, -1, 0, 2000, hit), CELL_MM);
        double s = StrictMath.sqrt(0.5);
        assertEquals(296 / s, g.castRay(200, 300, s, s, 2000, hit), CELL_MM / s);
        assertEquals(94, g.castRay(200, 700, 1, 0, 2000, hit), CELL_MM);
        assertEquals(LIGHT, hit.id);
    }

    @Test
    void clearLineSeesPastLightsButNotWalls() {
        Arena a = arena(1000, 1000, List.of(new Wall(500, 100, 500, 600, 8)),
                List.of(new Light(800, 800, 6, 400, 1, 0, 360)), List.of(new Cap(300, 800)));
        OccupancyGrid g = OccupancyGrid.of(a);
        assertTrue(g.clearLine(600, 500, 800, 800, LIGHT));
        assertFalse(g.clearLine(600, 500, 800, 800, FLOOR));
        assertFalse(g.clearLine(200, 300, 800, 300, LIGHT));
        assertTrue(g.clearLine(200, 700, 800, 700, LIGHT));
        assertFalse(g.clearLine(200, 800, 800, 800, LIGHT)); // the cap is in the way
        assertTrue(g.clearLine(400, 400, 400, 400, LIGHT));
        assertFalse(g.clearLine(500, 400, 500, 400, LIGHT));
        // Light itself passes over caps (too low to shade a sensor) but not through walls.
        assertTrue(g.lightReaches(200, 800, 800, 800));
        assertTrue(g.lightReaches(600, 500, 800, 800));
        assertFalse(g.lightReaches(200, 300, 800, 300));
        assertFalse(g.lightReaches(500, 400, 500, 400));
    }

    @Test
    void linesDoNotSlipThroughTouchingCorners() {
        OccupancyGrid g = new OccupancyGrid(20, 20);
        g.set(10, 10, WALL);
        g.set(11, 11, WALL);
        // Through the shared corner (11, 11) cells, from cell (10, 11) to cell (11, 10).
        assertFalse(g.clearLine(10.2 * CELL_MM, 11.8 * CELL_MM, 11.8 * CELL_MM, 10.2 * CELL_MM, LIGHT));
        RayHit hit = new RayHit();
        double s = StrictMath.sqrt(0.5);
        assertTrue(g.castRay(10.2 * CELL_MM, 11.8 * CELL_MM, s, -s, 100, hit) < 2 * CELL_MM);
    }
}
