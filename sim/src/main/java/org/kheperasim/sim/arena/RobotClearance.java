package org.kheperasim.sim.arena;

import java.util.List;
import java.util.Locale;

/**
 * The last check of an arena file: no robot starts overlapping a wall or lamp cell, the edge of
 * the grid (which is wall), or another robot. Caps may touch a robot: it pushes them.
 */
final class RobotClearance {

    private RobotClearance() {
    }

    /**
     * @param arena      the arena read
     * @param robotLines the line of each robot, in order
     * @param source     the file's name, for the error
     * @throws ArenaFormatException naming the first robot's line that overlaps something
     */
    static void check(Arena arena, List<Integer> robotLines, String source) {
        OccupancyGrid grid = OccupancyGrid.of(arena);
        double cell = grid.cellSize();
        List<Pose> robots = arena.robots();
        for (int i = 0; i < robots.size(); i++) {
            Pose p = robots.get(i);
            double radius = arena.robotType(i).body().radiusMm();
            double best = radius;
            int bestCol = 0;
            int bestRow = 0;
            for (int r = grid.row(p.y() - radius); r <= grid.row(p.y() + radius); r++) {
                for (int c = grid.col(p.x() - radius); c <= grid.col(p.x() + radius); c++) {
                    int id = grid.id(c, r);
                    if (id != OccupancyGrid.WALL && id != OccupancyGrid.LIGHT) {
                        continue;
                    }
                    double dx = Math.max(0, Math.max(c * cell - p.x(), p.x() - (c + 1) * cell));
                    double dy = Math.max(0, Math.max(r * cell - p.y(), p.y() - (r + 1) * cell));
                    double d = Math.sqrt(dx * dx + dy * dy);
                    if (d < best) {
                        best = d;
                        bestCol = c;
                        bestRow = r;
                    }
                }
            }
            if (best < radius) {
                boolean off = bestCol < 0 || bestRow < 0 || bestCol >= grid.cols() || bestRow >= grid.rows();
                String what = off ? "the edge of the arena"
                        : (grid.id(bestCol, bestRow) == OccupancyGrid.LIGHT ? "a light" : "a wall")
                        + String.format(Locale.ROOT, " near (%.1f, %.1f)",
                                grid.cellCentreX(bestCol), grid.cellCentreY(bestRow));
                throw new ArenaFormatException(source, robotLines.get(i), "robot at " + point(p) + " overlaps " + what
                        + "; its body is a " + Numbers.brief(radius) + " mm radius disc,"
                        + " so move its centre that far from walls, lights and the edge");
            }
            for (int j = 0; j < i; j++) {
                Pose q = robots.get(j);
                double d = Math.hypot(p.x() - q.x(), p.y() - q.y());
                if (d < 2 * radius) {
                    throw new ArenaFormatException(source, robotLines.get(i), "robot at " + point(p)
                            + " overlaps the robot on line " + robotLines.get(j) + ": their centres are "
                            + String.format(Locale.ROOT, "%.1f", d) + " mm apart, less than "
                            + Numbers.brief(2 * radius) + " mm; move one of them");
                }
            }
        }
    }

    private static String point(Pose p) {
        return "(" + Numbers.brief(p.x()) + ", " + Numbers.brief(p.y()) + ")";
    }
}
