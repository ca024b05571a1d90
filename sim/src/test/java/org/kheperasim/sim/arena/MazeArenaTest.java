package org.kheperasim.sim.arena;

import org.kheperasim.sim.engine.robot.RobotTypes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kheperasim.sim.arena.OccupancyGrid.FLOOR;
import static org.kheperasim.sim.arena.OccupancyGrid.WALL;

import java.util.ArrayDeque;
import java.util.Optional;
import java.util.function.IntPredicate;
import org.junit.jupiter.api.Test;

/** What the bundled arenas promise their users. */
class MazeArenaTest {

    private static final double LATTICE = 1219.2 / 5;
    /** A left-wall follower keeps about this far from the wall, mm. */
    private static final double FOLLOW_GAP = 20;

    private final Arena maze = ArenaFormat.loadBundled("maze");
    private final OccupancyGrid grid = OccupancyGrid.of(maze);

    /** Marks the 4-connected component of cells matching {@code member} that contains {@code start}. */
    private static boolean[] flood(OccupancyGrid g, int start, IntPredicate member) {
        boolean[] seen = new boolean[g.cols() * g.rows()];
        ArrayDeque<Integer> todo = new ArrayDeque<>();
        seen[start] = true;
        todo.add(start);
        int[][] steps = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        while (!todo.isEmpty()) {
            int i = todo.poll();
            int c = i % g.cols();
            int r = i / g.cols();
            for (int[] s : steps) {
                int nc = c + s[0];
                int nr = r + s[1];
                if (nc >= 0 && nr >= 0 && nc < g.cols() && nr < g.rows()) {
                    int n = nr * g.cols() + nc;
                    if (!seen[n] && member.test(n)) {
                        seen[n] = true;
                        todo.add(n);
                    }
                }
            }
        }
        return seen;
    }

    private int idOf(int index) {
        return grid.id(index % grid.cols(), index / grid.cols());
    }

    @Test
    void everyWallIsJoinedToTheBorder() {
        // Cell 0 is the lower-left corner, on the border wall.
        assertEquals(WALL, idOf(0));
        boolean[] joined = flood(grid, 0, i -> idOf(i) == WALL);
        for (int i = 0; i < joined.length; i++) {
            if (idOf(i) == WALL) {
                assertTrue(joined[i], "wall cell " + (i % grid.cols()) + "," + (i / grid.cols()) + " is an island");
            }
        }
    }

    @Test
    void theFloorIsOneConnectedSpace() {
        Pose start = maze.robots().get(0);
        int first = grid.row(start.y()) * grid.cols() + grid.col(start.x());
        boolean[] reached = flood(grid, first, i -> idOf(i) == FLOOR);
        for (int i = 0; i < reached.length; i++) {
            if (idOf(i) == FLOOR) {
                assertTrue(reached[i], "floor cell " + (i % grid.cols()) + "," + (i / grid.cols()) + " is cut off");
            }
        }
    }

    @Test
    void aWallFollowingRobotFitsEverywhereAndPassesThroughEveryCellRegion() {
        DistanceField df = DistanceField.of(grid);
        double need = RobotTypes.KHEPERA1.body().radiusMm() + FOLLOW_GAP;
        Pose start = maze.robots().get(0);
        assertTrue(df.clearance(start.x(), start.y()) > need);
        int first = grid.row(start.y()) * grid.cols() + grid.col(start.x());
        IntPredicate roomy = i -> df.clearance(grid.cellCentreX(i % grid.cols()), grid.cellCentreY(i / grid.cols())) >= need;
        boolean[] reachable = flood(grid, first, roomy);
        for (int col = 0; col < 5; col++) {
            for (int row = 0; row < 5; row++) {
                String name = "c" + col + "_" + row;
                Optional<Region> region = maze.region(name);
                assertTrue(region.isPresent(), name);
                Region r = region.get();
                assertTrue(r.x1() >= col * LATTICE && r.x2() <= (col + 1) * LATTICE
                        && r.y1() >= row * LATTICE && r.y2() <= (row + 1) * LATTICE, name + " lies in its cell");
                // A robot hugging any wall of the cell at the follow gap has its centre inside the region.
                assertTrue(r.x1() - col * LATTICE < 4 + need, name);
                boolean entered = false;
                for (int gr = grid.row(r.y1()); gr <= grid.row(r.y2()) && !entered; gr++) {
                    for (int gc = grid.col(r.x1()); gc <= grid.col(r.x2()) && !entered; gc++) {
                        entered = reachable[gr * grid.cols() + gc];
                    }
                }
                assertTrue(entered, "the robot can reach region " + name);
            }
        }
        assertEquals(25, maze.regions().size());
    }

    @Test
    void wallsMeetAtLatticePointsAndCorridorsAreACellWide() {
        for (Wall w : maze.walls()) {
            assertEquals(8, w.thickness());
            boolean border = w.x1() == 4 || w.y1() == 4 || w.x1() == 1215.2 || w.y1() == 1215.2;
            if (!border) {
                for (double v : new double[] {w.x1(), w.y1(), w.x2(), w.y2()}) {
                    double k = v / LATTICE;
                    assertEquals(Math.rint(k), k, 1e-9, "wall end " + v + " is on the lattice");
                }
                assertTrue(w.x1() == w.x2() || w.y1() == w.y2(), "interior walls follow lattice lines");
            }
        }
    }

    @Test
    void robotStartsInACornerFacingDownItsCorridor() {
        Pose start = maze.robots().get(0);
        assertEquals(1, maze.robots().size());
        assertTrue(maze.region("c0_0").orElseThrow().contains(start.x(), start.y()));
        double a = StrictMath.toRadians(start.headingDeg());
        RayHit hit = new RayHit();
        double ahead = grid.castRay(start.x(), start.y(), StrictMath.cos(a), StrictMath.sin(a), 2000, hit);
        assertTrue(ahead > 3 * LATTICE, "open corridor ahead: " + ahead);
        // The wall to follow is close on the left.
        double left = grid.castRay(start.x(), start.y(), -StrictMath.sin(a), StrictMath.cos(a), 2000, hit);
        assertTrue(left < LATTICE / 2, "wall on the left: " + left);
    }

    @Test
    void labIsTheEmptyEnclosure() {
        Arena lab = ArenaFormat.loadBundled("lab");
        assertEquals(1219.2, lab.width());
        assertEquals(1219.2, lab.height());
        assertEquals(new Pose(609.6, 609.6, 90), lab.robots().get(0));
        assertEquals(4, lab.walls().size());
        assertEquals(4, lab.regions().size());
        assertTrue(lab.region("upper_right").orElseThrow().contains(1000, 1000));
        assertTrue(lab.region("lower_left").orElseThrow().contains(100, 100));
    }
}
