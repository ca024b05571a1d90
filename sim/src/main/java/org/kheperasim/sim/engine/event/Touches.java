package org.kheperasim.sim.engine.event;

import java.util.List;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.OccupancyGrid;
import org.kheperasim.sim.arena.Wall;
import org.kheperasim.sim.engine.SimRobot;
import org.kheperasim.sim.engine.space.World;
import org.kheperasim.sim.engine.view.CapView;
import org.kheperasim.sim.engine.view.Contact;

/**
 * Names what the engine's touch point is: the engine's contact handling touches either the centre of
 * the obstacle cell nearest the body (a wall, a lamp, a cap painted in the grid, or the padding cell
 * just outside the arena's edge), another robot's centre, or a blocking cap's centre. The grid is read
 * first: a robot moved on the engine's second thread only ever touches grid cells, so it never reads
 * another robot's position while that one moves.
 */
final class Touches {
    /** The engine's touching margin (its contact handling's), mm. */
    static final double TOUCH_MM = 0.5;

    private final World world;
    private final List<SimRobot> robots;

    Touches(World world, List<SimRobot> robots) {
        this.world = world;
        this.robots = robots;
    }

    /**
     * @param robot a robot whose contact flag is not NONE
     * @return what it touches, or null when the touch point is no longer anything (another robot that
     *     has moved away from a robot standing still: the engine keeps the flag until it moves)
     */
    Touched of(SimRobot robot) {
        double[] p = robot.touchPoint();
        OccupancyGrid grid = world.grid();
        int col = grid.col(p[0]);
        int row = grid.row(p[1]);
        if (col < 0 || row < 0 || col >= grid.cols() || row >= grid.rows()) {
            return Touched.EDGE;
        }
        int id = grid.id(col, row);
        Arena a = world.arena();
        if (id == OccupancyGrid.WALL) {
            return new Touched(Touched.Kind.WALL, nearestWall(a.walls(), p[0], p[1]));
        }
        if (id == OccupancyGrid.LIGHT) {
            return new Touched(Touched.Kind.LAMP, nearestLamp(a.lights(), p[0], p[1]));
        }
        if (id >= OccupancyGrid.FIRST_CAP) {
            return new Touched(Touched.Kind.CAP, id - OccupancyGrid.FIRST_CAP);
        }
        for (SimRobot o : robots) {
            if (o != robot && o.x() == p[0] && o.y() == p[1]) {
                return new Touched(Touched.Kind.ROBOT, o.id());
            }
        }
        List<CapView> caps = world.caps();
        for (int c = 0; c < caps.size(); c++) {
            if (caps.get(c).x() == p[0] && caps.get(c).y() == p[1]) {
                return new Touched(Touched.Kind.CAP, c);
            }
        }
        return null;
    }

    /**
     * @return the first cap (arena order) on the floor or in another robot's gripper whose body is within
     *     the engine's touching margin of this robot's body, or -1: a cap being pushed aside, which the
     *     engine's contact flag does not show (only a cap that blocks the robot is flagged)
     */
    int pushedCap(SimRobot robot) {
        List<CapView> caps = world.caps();
        double radius = robot.type().body().radiusMm();
        for (int c = 0; c < caps.size(); c++) {
            CapView cap = caps.get(c);
            double gap = StrictMath.hypot(robot.x() - cap.x(), robot.y() - cap.y()) - cap.radius() - radius;
            if (cap.heldBy() != robot.id() && gap <= TOUCH_MM) {
                return c;
            }
        }
        return -1;
    }

    /** @return the side of the robot cap {@code c} lies on */
    Contact sideOfCap(SimRobot robot, int c) {
        CapView cap = world.caps().get(c);
        double rel = StrictMath.atan2(cap.y() - robot.y(), cap.x() - robot.x())
                - StrictMath.toRadians(robot.headingDeg());
        return Contact.ofAngle(rel);
    }

    private static int nearestWall(List<Wall> walls, double x, double y) {
        int best = -1;
        double gap = Double.POSITIVE_INFINITY;
        for (int k = 0; k < walls.size(); k++) {
            Wall w = walls.get(k);
            double g = segmentDistance(x, y, w.x1(), w.y1(), w.x2(), w.y2()) - w.thickness() / 2;
            if (g < gap) {
                gap = g;
                best = k;
            }
        }
        return best;
    }

    private static int nearestLamp(List<Light> lights, double x, double y) {
        int best = -1;
        double gap = Double.POSITIVE_INFINITY;
        for (int k = 0; k < lights.size(); k++) {
            Light l = lights.get(k);
            double g = StrictMath.hypot(x - l.x(), y - l.y()) - l.radius();
            if (g < gap) {
                gap = g;
                best = k;
            }
        }
        return best;
    }

    /** @return the distance from (px, py) to the segment from (x1, y1) to (x2, y2), mm */
    static double segmentDistance(double px, double py, double x1, double y1, double x2, double y2) {
        double dx = x2 - x1;
        double dy = y2 - y1;
        double len2 = dx * dx + dy * dy;
        double u = len2 == 0 ? 0 : ((px - x1) * dx + (py - y1) * dy) / len2;
        u = StrictMath.max(0, StrictMath.min(1, u));
        return StrictMath.hypot(px - (x1 + u * dx), py - (y1 + u * dy));
    }
}
