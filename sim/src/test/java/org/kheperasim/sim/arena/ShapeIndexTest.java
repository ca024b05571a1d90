package org.kheperasim.sim.arena;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The shapes the proximity beams are cast against: a beam meets a wall's capsule or a lamp's disc
 * where a fine march along it first enters the shape; the buckets miss no shape near a point; the
 * lattice's clearance never exceeds the true distance to the nearest shape or the floor's edge.
 */
class ShapeIndexTest {

    static List<String> arenas() {
        return ArenaFormat.bundledNames();
    }

    @Test
    void aBeamMeetsAShapeWhereAMarchAlongItEntersIt() {
        SplittableRandom random = new SplittableRandom(3);
        int hits = 0;
        for (int n = 0; n < 1000; n++) {
            boolean lamp = n % 5 == 0;
            List<Wall> walls = lamp ? List.of() : List.of(new Wall(random.nextDouble(200, 400),
                    random.nextDouble(200, 400), random.nextDouble(200, 400), random.nextDouble(200, 400),
                    random.nextDouble(0.5, 30)));
            List<Light> lights = lamp ? List.of(new Light(random.nextDouble(250, 350), random.nextDouble(250, 350),
                    random.nextDouble(1, 20), 400, 1, 0, 360)) : List.of();
            Arena arena = new Arena("t", 600, 600, List.of(new Pose(50, 50, 0)), walls, lights, List.of(), List.of());
            ShapeIndex index = new ShapeIndex(arena, OccupancyGrid.of(arena));
            double px = random.nextDouble(180, 420);
            double py = random.nextDouble(180, 420);
            // Half the beams aimed near the shape's middle, the rest anywhere.
            double h = n % 2 == 0 ? random.nextDouble(2 * StrictMath.PI)
                    : StrictMath.atan2(300 - py, 300 - px) + random.nextDouble(-0.3, 0.3);
            double rx = StrictMath.cos(h);
            double ry = StrictMath.sin(h);
            double t = index.along(0, px, py, rx, ry);
            double step = 0.02;
            double march = Double.POSITIVE_INFINITY;
            for (double s = 0; s < 300; s += step) {
                if (index.surface(0, px + s * rx, py + s * ry) <= 0) {
                    march = s;
                    break;
                }
            }
            String where = "shape " + (lamp ? lights : walls) + " from (" + px + ", " + py + ") heading " + h;
            if (march == Double.POSITIVE_INFINITY) {
                // A miss, or a graze the march stepped over: the beam's point there is on the surface.
                assertTrue(t == Double.POSITIVE_INFINITY || index.surface(0, px + t * rx, py + t * ry) > -1e-3,
                        where);
            } else {
                hits++;
                assertTrue(t <= march && t > march - step - 1e-9, where + ": cast " + t + ", march " + march);
                if (march > 0) {
                    assertEquals(0, index.surface(0, px + t * rx, py + t * ry), 1e-9, where);
                } else {
                    assertEquals(0, t, where + ": a beam from inside meets the shape at once");
                }
            }
        }
        assertTrue(hits > 300, "only " + hits + " beams met their shape");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("arenas")
    void theBucketsAndTheLatticeAgreeWithEveryShape(String name) {
        Arena arena = ArenaFormat.resolve(name);
        OccupancyGrid grid = OccupancyGrid.of(arena);
        ShapeIndex index = new ShapeIndex(arena, grid);
        assertEquals(arena.walls().size() + arena.lights().size(), index.count());
        SplittableRandom random = new SplittableRandom(name.hashCode());
        int[] out = new int[index.count()];
        int[] seen = new int[index.count()];
        double edgeX = grid.cols() * OccupancyGrid.CELL_MM;
        double edgeY = grid.rows() * OccupancyGrid.CELL_MM;
        for (int n = 1; n <= 5_000; n++) {
            double x = random.nextDouble(edgeX);
            double y = random.nextDouble(edgeY);
            double radius = random.nextDouble(150);
            int found = index.gather(x, y, radius, out, seen, n);
            double nearest = StrictMath.min(StrictMath.min(x, edgeX - x), StrictMath.min(y, edgeY - y));
            for (int k = 0; k < index.count(); k++) {
                double d = index.surface(k, x, y);
                nearest = StrictMath.min(nearest, d);
                boolean listed = false;
                for (int i = 0; i < found; i++) {
                    listed |= out[i] == k;
                }
                assertEquals(d <= radius, listed, name + ": shape " + k + " at " + d + " mm from (" + x + ", " + y
                        + "), radius " + radius);
            }
            assertTrue(index.clearBelow(x, y) <= nearest, name + ": the lattice's bound at (" + x + ", " + y + ") is "
                    + index.clearBelow(x, y) + ", the nearest shape or edge " + nearest);
        }
    }
}
