package org.kheperasim.sim.arena.wsu;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.Wall;
import org.kheperasim.sim.arena.wsu.WallRuns.Bar;
import org.kheperasim.sim.arena.wsu.WsuWorldObjects.WsuObject;

/**
 * Turns a WSU world's objects into our arena model: the original's 500 x 500 pixel panel (origin
 * top-left, y down) becomes the 1219.2 mm square lab (origin bottom-left, y up), one pixel per grid
 * cell of 2.4384 mm.
 *
 * <ul>
 *   <li>The border walls the original always has (not stored in files) are added: solid in rows
 *       0..18 and 482..499 and in columns 0..18 and 484..499.</li>
 *   <li>A wall is an 8 x 50 px bar: with {@code theta == 0} vertical, {@code x..x+7} by
 *       {@code y..y+49}; with any other angle horizontal, {@code x..x+49} by {@code y-8..y-1}. It
 *       becomes a wall of the bar's short side as thickness along its long centre line, the ends
 *       drawn in by half the thickness, so the rounded ends stay inside the bar (its corners are
 *       rounded off by up to 4 px); an end cut by the panel's edge is not drawn in. Bars laid end to
 *       end in a line are first joined into one run ({@link WallRuns}), so the joints stay solid.</li>
 *   <li>A cap or ball is a 9 x 9 px disc (a cap of radius 4.5 px); a light is a 16 x 16 px lamp body
 *       (a lamp of radius 8 px) that shines 250 px all around.</li>
 *   <li>What lies partly outside the panel is clipped to it; what lies wholly outside is left out,
 *       with a warning.</li>
 *   <li>The robot starts where the original starts it, centre (263, 263) px facing east; when an
 *       object covers that spot, at the nearest free spot, with a warning.</li>
 * </ul>
 */
final class WsuArenaBuilder {
    /** Side of the original's panel, px. */
    static final int PANEL_PX = 500;
    /** One pixel of the panel, mm: the paper's 4 ft lab over 500 px (one occupancy-grid cell). */
    static final double MM_PER_PX = 1219.2 / PANEL_PX;
    /** Where the original starts the robot's centre, px from the panel's left and top. */
    static final double START_X_PX = 263;
    static final double START_Y_PX = 263;

    private static final int WALL_LONG_PX = 50;
    private static final int WALL_SHORT_PX = 8;
    private static final double CAP_RADIUS_PX = 4.5;
    private static final double LAMP_RADIUS_PX = 8;
    private static final double LAMP_RANGE_PX = 250;
    /** Shortest centre line given to a square piece of wall, px (a wall's two ends must differ). */
    private static final double MIN_LINE_PX = 0.5;

    private final String source;
    private final Consumer<String> warnings;
    private final List<Bar> bars = new ArrayList<>();
    private final List<Wall> walls = new ArrayList<>();
    private final List<Light> lights = new ArrayList<>();
    private final List<Cap> caps = new ArrayList<>();

    private WsuArenaBuilder(String source, Consumer<String> warnings) {
        this.source = source;
        this.warnings = warnings;
    }

    /**
     * @param name     the arena's name (letters, digits, {@code _}, {@code -})
     * @param objects  the world's objects, in file order
     * @param source   the file's name, for messages
     * @param warnings where to say what was clipped, left out or moved
     * @return the arena
     * @throws WsuWorldException when the robot fits nowhere
     */
    static Arena build(String name, List<WsuObject> objects, String source, Consumer<String> warnings) {
        return new WsuArenaBuilder(source, warnings).arena(name, objects);
    }

    private Arena arena(String name, List<WsuObject> objects) {
        // The border: left, right, top, bottom.
        wall(new Bar(0, 0, 19, PANEL_PX, 0));
        wall(new Bar(484, 0, PANEL_PX, PANEL_PX, 0));
        wall(new Bar(0, 0, PANEL_PX, 19, 0));
        wall(new Bar(0, 482, PANEL_PX, PANEL_PX, 0));
        for (WsuObject o : objects) {
            switch (o.type()) {
                case WsuObject.WALL -> {
                    double x = o.x(); // in double: a damaged file's coordinates must not overflow
                    double y = o.y();
                    if (o.theta() == 0) {
                        bar(x, y, x + WALL_SHORT_PX, y + WALL_LONG_PX, o);
                    } else {
                        bar(x, y - WALL_SHORT_PX, x + WALL_LONG_PX, y, o);
                    }
                }
                case WsuObject.CAP, WsuObject.BALL -> {
                    double[] c = disc(o, CAP_RADIUS_PX);
                    if (c != null) {
                        caps.add(new Cap(mmX(c[0]), mmY(c[1]), mm(CAP_RADIUS_PX)));
                    }
                }
                case WsuObject.LIGHT -> {
                    double[] c = disc(o, LAMP_RADIUS_PX);
                    if (c != null) {
                        lights.add(new Light(mmX(c[0]), mmY(c[1]), mm(LAMP_RADIUS_PX), mm(LAMP_RANGE_PX),
                                Light.DEFAULT_INTENSITY, Light.DEFAULT_DIRECTION, Light.DEFAULT_SPREAD));
                    }
                }
                default -> warnings.accept(what(o) + " is of kind " + o.type() + ", which the WSU simulator does not"
                        + " have (1 wall, 2 cap, 3 ball, 4 light); left out");
            }
        }
        for (Bar run : WallRuns.join(bars)) {
            wall(run);
        }
        double side = PANEL_PX * MM_PER_PX;
        Pose wanted = new Pose(mmX(START_X_PX), mmY(START_Y_PX), 0);
        Arena draft = new Arena(name, side, side, List.of(wanted), walls, lights, caps, List.of());
        double[] free = RobotPlacement.nearestFree(draft, wanted.x(), wanted.y());
        if (free == null) {
            throw new WsuWorldException(source, -1, "the robot (a 55 mm disc) fits nowhere in this world: walls and"
                    + " lights cover every place; remove some in the WSU simulator and save the world again");
        }
        Pose start = new Pose(round(free[0]), round(free[1]), 0);
        if (!start.equals(wanted)) {
            warnings.accept(String.format(Locale.ROOT, "the original's robot start, centre (%.0f, %.0f) px ="
                    + " (%.1f, %.1f) mm, is covered by an object; the robot starts at the nearest free spot,"
                    + " (%.1f, %.1f) mm", START_X_PX, START_Y_PX, wanted.x(), wanted.y(), start.x(), start.y()));
        }
        return new Arena(name, side, side, List.of(start), walls, lights, caps, List.of());
    }

    /**
     * A wall bar of the file, px edges {@code [x0, x1) x [y0, y1)} (y down), clipped to the panel, kept for joining.
     */
    private void bar(double x0, double y0, double x1, double y1, WsuObject o) {
        double cx0 = Math.max(0, x0);
        double cy0 = Math.max(0, y0);
        double cx1 = Math.min(PANEL_PX, x1);
        double cy1 = Math.min(PANEL_PX, y1);
        if (cx1 <= cx0 || cy1 <= cy0) {
            warnings.accept(what(o) + " lies wholly outside the 500 x 500 px panel; left out");
            return;
        }
        if (cx0 != x0 || cy0 != y0 || cx1 != x1 || cy1 != y1) {
            warnings.accept(what(o) + " reaches outside the panel; clipped to it");
        }
        bars.add(new Bar(cx0, cy0, cx1, cy1, bars.size()));
    }

    /** A solid rectangle inside the panel as a wall along its longer side. */
    private void wall(Bar b) {
        double w = b.x1() - b.x0();
        double h = b.y1() - b.y0();
        if (w >= h) {
            double[] ends = line(b.x0(), b.x1(), h);
            double y = (b.y0() + b.y1()) / 2;
            walls.add(new Wall(mmX(ends[0]), mmY(y), mmX(ends[1]), mmY(y), mm(h)));
        } else {
            double[] ends = line(b.y0(), b.y1(), w);
            double x = (b.x0() + b.x1()) / 2;
            walls.add(new Wall(mmX(x), mmY(ends[0]), mmX(x), mmY(ends[1]), mm(w)));
        }
    }

    /**
     * The centre line's ends along the long side {@code [a, b)}: drawn in by half the thickness unless at the panel's
     * edge.
     */
    private static double[] line(double a, double b, double thickness) {
        double start = a > 0 ? a + thickness / 2 : a;
        double end = b < PANEL_PX ? b - thickness / 2 : b;
        if (end - start < MIN_LINE_PX) {
            double mid = (a + b) / 2;
            start = mid - MIN_LINE_PX / 2;
            end = mid + MIN_LINE_PX / 2;
        }
        return new double[] {start, end};
    }

    /**
     * The centre of a disc anchored at its bounding square's top-left, clipped into the panel; null when wholly
     * outside.
     */
    private double[] disc(WsuObject o, double radius) {
        double x = o.x() + radius;
        double y = o.y() + radius;
        if (x + radius <= 0 || y + radius <= 0 || x - radius >= PANEL_PX || y - radius >= PANEL_PX) {
            warnings.accept(what(o) + " lies wholly outside the 500 x 500 px panel; left out");
            return null;
        }
        double cx = Math.min(PANEL_PX, Math.max(0, x));
        double cy = Math.min(PANEL_PX, Math.max(0, y));
        if (cx != x || cy != y) {
            warnings.accept(what(o) + " has its centre outside the panel; moved onto the panel's edge");
        }
        return new double[] {cx, cy};
    }

    private static String what(WsuObject o) {
        String kind = switch (o.type()) {
            case WsuObject.WALL -> "wall";
            case WsuObject.CAP -> "cap";
            case WsuObject.BALL -> "ball";
            case WsuObject.LIGHT -> "light";
            default -> "object";
        };
        return String.format(Locale.ROOT, "%s %d at (%d, %d) px (byte %d)", kind, o.id(), o.x(), o.y(), o.offset());
    }

    /** @return a length in px as mm */
    static double mm(double px) {
        return round(px * MM_PER_PX);
    }

    /** @return a panel x (px from the left) as arena x, mm */
    static double mmX(double px) {
        return mm(px);
    }

    /** @return a panel y (px from the top, down) as arena y (mm from the bottom, up) */
    static double mmY(double px) {
        return mm(PANEL_PX - px);
    }

    /** Millimetres to 0.1 µm: the exact decimal of px x 2.4384, without binary noise in the text file. */
    private static double round(double mm) {
        return Math.round(mm * 10_000) / 10_000.0;
    }
}
