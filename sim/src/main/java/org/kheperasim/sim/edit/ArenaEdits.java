package org.kheperasim.sim.edit;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.Wall;

/**
 * Edits of the arena model as pure functions: each takes an arena and returns a new one (the
 * record is immutable). The editing tools and the undo stack are built on these. Millimetres and
 * degrees throughout.
 */
public final class ArenaEdits {
    /** Thickness of a wall drawn with the wall tool, mm (the lab's walls). */
    public static final double WALL_THICKNESS = 8;

    private ArenaEdits() {
    }

    /** @return a copy with the given lists */
    public static Arena with(Arena a, List<Pose> robots, List<Wall> walls, List<Light> lights, List<Cap> caps) {
        return new Arena(a.name(), a.width(), a.height(), robots, walls, lights, caps, a.regions(), a.assignment(),
                a.kindsFor(robots));
    }

    /** @return the arena with a wall from (x1, y1) to (x2, y2) added */
    public static Arena addWall(Arena a, double x1, double y1, double x2, double y2) {
        List<Wall> walls = new ArrayList<>(a.walls());
        walls.add(new Wall(x1, y1, x2, y2, WALL_THICKNESS));
        return with(a, a.robots(), walls, a.lights(), a.caps());
    }

    /** @return the arena with a default lamp at (x, y) */
    public static Arena addLight(Arena a, double x, double y) {
        List<Light> lights = new ArrayList<>(a.lights());
        lights.add(new Light(x, y));
        return with(a, a.robots(), a.walls(), lights, a.caps());
    }

    /** @return the arena with a default cap at (x, y) */
    public static Arena addCap(Arena a, double x, double y) {
        List<Cap> caps = new ArrayList<>(a.caps());
        caps.add(new Cap(x, y));
        return with(a, a.robots(), a.walls(), a.lights(), caps);
    }

    /** @return the arena with robot {@code index} starting at {@code pose} */
    public static Arena setRobot(Arena a, int index, Pose pose) {
        List<Pose> robots = new ArrayList<>(a.robots());
        robots.set(index, pose);
        return with(a, robots, a.walls(), a.lights(), a.caps());
    }

    /** @return the arena with one end (0 or 1) of wall {@code index} moved to (x, y) */
    public static Arena setWallEnd(Arena a, int index, int end, double x, double y) {
        List<Wall> walls = new ArrayList<>(a.walls());
        Wall w = walls.get(index);
        walls.set(index, end == 0 ? new Wall(x, y, w.x2(), w.y2(), w.thickness())
                : new Wall(w.x1(), w.y1(), x, y, w.thickness()));
        return with(a, a.robots(), walls, a.lights(), a.caps());
    }

    /** @return the arena with every item of {@code items} moved by (dx, dy) mm */
    public static Arena move(Arena a, Collection<Item> items, double dx, double dy) {
        List<Pose> robots = new ArrayList<>(a.robots());
        List<Wall> walls = new ArrayList<>(a.walls());
        List<Light> lights = new ArrayList<>(a.lights());
        List<Cap> caps = new ArrayList<>(a.caps());
        for (Item it : items) {
            int i = it.index();
            switch (it.kind()) {
                case ROBOT -> {
                    Pose p = robots.get(i);
                    robots.set(i, new Pose(p.x() + dx, p.y() + dy, p.headingDeg()));
                }
                case WALL -> {
                    Wall w = walls.get(i);
                    walls.set(i, new Wall(w.x1() + dx, w.y1() + dy, w.x2() + dx, w.y2() + dy, w.thickness()));
                }
                case LIGHT -> {
                    Light l = lights.get(i);
                    lights.set(i, new Light(l.x() + dx, l.y() + dy, l.radius(), l.range(), l.intensity(),
                            l.directionDeg(), l.spreadDeg()));
                }
                case CAP -> {
                    Cap c = caps.get(i);
                    caps.set(i, new Cap(c.x() + dx, c.y() + dy, c.radius()));
                }
            }
        }
        return with(a, robots, walls, lights, caps);
    }

    /**
     * Rotate items about the centre of their bounding box: walls turn about it, robots and
     * directional lamps also turn their heading.
     *
     * @param deg counter-clockwise, degrees
     * @return the arena rotated
     */
    public static Arena rotate(Arena a, Collection<Item> items, double deg) {
        if (items.isEmpty()) {
            return a;
        }
        double[] c = centre(a, items);
        double cos = StrictMath.cos(StrictMath.toRadians(deg));
        double sin = StrictMath.sin(StrictMath.toRadians(deg));
        List<Pose> robots = new ArrayList<>(a.robots());
        List<Wall> walls = new ArrayList<>(a.walls());
        List<Light> lights = new ArrayList<>(a.lights());
        List<Cap> caps = new ArrayList<>(a.caps());
        for (Item it : items) {
            int i = it.index();
            switch (it.kind()) {
                case ROBOT -> {
                    Pose p = robots.get(i);
                    double[] q = turn(p.x(), p.y(), c, cos, sin);
                    robots.set(i, new Pose(q[0], q[1], normalise(p.headingDeg() + deg)));
                }
                case WALL -> {
                    Wall w = walls.get(i);
                    double[] p1 = turn(w.x1(), w.y1(), c, cos, sin);
                    double[] p2 = turn(w.x2(), w.y2(), c, cos, sin);
                    walls.set(i, new Wall(round(p1[0]), round(p1[1]), round(p2[0]), round(p2[1]), w.thickness()));
                }
                case LIGHT -> {
                    Light l = lights.get(i);
                    double[] q = turn(l.x(), l.y(), c, cos, sin);
                    lights.set(i, new Light(round(q[0]), round(q[1]), l.radius(), l.range(), l.intensity(),
                            normalise(l.directionDeg() + deg), l.spreadDeg()));
                }
                case CAP -> {
                    Cap cap = caps.get(i);
                    double[] q = turn(cap.x(), cap.y(), c, cos, sin);
                    caps.set(i, new Cap(round(q[0]), round(q[1]), cap.radius()));
                }
            }
        }
        return with(a, robots, walls, lights, caps);
    }

    /**
     * Delete items (robots cannot be deleted: an arena needs its start poses; they are skipped).
     *
     * @return the arena without them
     */
    public static Arena delete(Arena a, Collection<Item> items) {
        Set<Integer> walls = indices(items, Item.Kind.WALL);
        Set<Integer> lights = indices(items, Item.Kind.LIGHT);
        Set<Integer> caps = indices(items, Item.Kind.CAP);
        return with(a, a.robots(), keep(a.walls(), walls), keep(a.lights(), lights), keep(a.caps(), caps));
    }

    /** @return the items of {@code a} whose reference point lies in the rectangle */
    public static List<Item> inside(Arena a, double x1, double y1, double x2, double y2) {
        double lx = StrictMath.min(x1, x2);
        double hx = StrictMath.max(x1, x2);
        double ly = StrictMath.min(y1, y2);
        double hy = StrictMath.max(y1, y2);
        List<Item> out = new ArrayList<>();
        for (int i = 0; i < a.robots().size(); i++) {
            if (in(a.robots().get(i).x(), a.robots().get(i).y(), lx, ly, hx, hy)) {
                out.add(new Item(Item.Kind.ROBOT, i));
            }
        }
        for (int i = 0; i < a.walls().size(); i++) {
            Wall w = a.walls().get(i);
            if (in(w.x1(), w.y1(), lx, ly, hx, hy) && in(w.x2(), w.y2(), lx, ly, hx, hy)) {
                out.add(new Item(Item.Kind.WALL, i));
            }
        }
        for (int i = 0; i < a.lights().size(); i++) {
            if (in(a.lights().get(i).x(), a.lights().get(i).y(), lx, ly, hx, hy)) {
                out.add(new Item(Item.Kind.LIGHT, i));
            }
        }
        for (int i = 0; i < a.caps().size(); i++) {
            if (in(a.caps().get(i).x(), a.caps().get(i).y(), lx, ly, hx, hy)) {
                out.add(new Item(Item.Kind.CAP, i));
            }
        }
        return out;
    }

    /** @return a new empty arena of the given size, with a border of walls and one robot in the middle */
    public static Arena blank(String name, double width, double height) {
        double t = WALL_THICKNESS;
        List<Wall> border = List.of(new Wall(0, t / 2, width, t / 2, t),
                new Wall(0, height - t / 2, width, height - t / 2, t),
                new Wall(t / 2, 0, t / 2, height, t), new Wall(width - t / 2, 0, width - t / 2, height, t));
        return new Arena(name, width, height, List.of(new Pose(width / 2, height / 2, 90)), border, List.of(),
                List.of(), List.of());
    }

    private static boolean in(double x, double y, double lx, double ly, double hx, double hy) {
        return x >= lx && x <= hx && y >= ly && y <= hy;
    }

    private static <T> List<T> keep(List<T> list, Set<Integer> drop) {
        List<T> out = new ArrayList<>();
        for (int i = 0; i < list.size(); i++) {
            if (!drop.contains(i)) {
                out.add(list.get(i));
            }
        }
        return out;
    }

    private static Set<Integer> indices(Collection<Item> items, Item.Kind kind) {
        Set<Integer> out = new TreeSet<>();
        for (Item it : items) {
            if (it.kind() == kind) {
                out.add(it.index());
            }
        }
        return out;
    }

    private static double[] centre(Arena a, Collection<Item> items) {
        double lx = Double.MAX_VALUE;
        double ly = Double.MAX_VALUE;
        double hx = -Double.MAX_VALUE;
        double hy = -Double.MAX_VALUE;
        for (Item it : items) {
            double[] pts = switch (it.kind()) {
                case ROBOT -> new double[] {a.robots().get(it.index()).x(), a.robots().get(it.index()).y()};
                case WALL -> {
                    Wall w = a.walls().get(it.index());
                    yield new double[] {w.x1(), w.y1(), w.x2(), w.y2()};
                }
                case LIGHT -> new double[] {a.lights().get(it.index()).x(), a.lights().get(it.index()).y()};
                case CAP -> new double[] {a.caps().get(it.index()).x(), a.caps().get(it.index()).y()};
            };
            for (int k = 0; k < pts.length; k += 2) {
                lx = StrictMath.min(lx, pts[k]);
                hx = StrictMath.max(hx, pts[k]);
                ly = StrictMath.min(ly, pts[k + 1]);
                hy = StrictMath.max(hy, pts[k + 1]);
            }
        }
        return new double[] {(lx + hx) / 2, (ly + hy) / 2};
    }

    private static double[] turn(double x, double y, double[] c, double cos, double sin) {
        double dx = x - c[0];
        double dy = y - c[1];
        return new double[] {c[0] + dx * cos - dy * sin, c[1] + dx * sin + dy * cos};
    }

    /** Rounds to 0.01 mm, so rotated files stay readable. */
    public static double round(double v) {
        return StrictMath.rint(v * 100) / 100;
    }

    public static double normalise(double deg) {
        double d = deg % 360;
        return d < 0 ? d + 360 : d;
    }
}
