package org.kheperasim.sim.gui;

import java.awt.AlphaComposite;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.MultipleGradientPaint;
import java.awt.RadialGradientPaint;
import java.awt.RenderingHints;
import java.awt.Stroke;
import java.awt.geom.Arc2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.util.List;
import java.util.Set;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.Cap;
import org.kheperasim.sim.arena.Light;
import org.kheperasim.sim.arena.Pose;
import org.kheperasim.sim.arena.Region;
import org.kheperasim.sim.arena.Wall;
import org.kheperasim.sim.edit.EditorModel;
import org.kheperasim.sim.edit.Item;
import org.kheperasim.sim.edit.ItemHits;
import org.kheperasim.sim.engine.robot.GripperTurret;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.view.CapView;
import org.kheperasim.sim.engine.view.GripperView;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * Draws an arena and a snapshot of a run into a {@link Graphics2D}: floor, regions, lamps, walls,
 * caps, trails, robots with their heading, gripper and sensor beams, the editor's selection and
 * handles. The Swing view only hosts this call, so drawing is testable into a BufferedImage.
 * Hit-testing against the same shapes is {@link ItemHits}.
 */
public final class ArenaRenderer {
    /** Colours, public so tests can look for them. */
    public static final Color FLOOR = new Color(0xF4F1E8);
    /** Around the arena. */
    public static final Color OUTSIDE = new Color(0x6B6F76);
    /** Walls. */
    public static final Color WALL = new Color(0x3A3F4B);
    /** The robot's body. */
    public static final Color ROBOT = new Color(0x2E8B57);
    /** Caps on the floor. */
    public static final Color CAP = new Color(0xD03030);
    /** Lamp bodies. */
    public static final Color LAMP = new Color(0xF0A000);
    /** Selection. */
    public static final Color SELECTION = new Color(0x1E6FFF);
    /** A refused edit. */
    public static final Color REFUSED = new Color(0xE00000);

    /** Handle size, px. */
    static final double HANDLE_PX = 8;
    static final Color LED_ON = new Color(0xFFE030);
    private static final Color LED_OFF = new Color(0x1E5A38);
    /** Distance of the heading handle ahead of a robot's centre, mm. */
    static final double HEADING_HANDLE_MM = ItemHits.HEADING_HANDLE_MM;

    /**
     * What to draw besides the model.
     *
     * @param beams draw the proximity sensors' beams
     * @param trail draw the robots' trails
     * @param grid draw a 100 mm grid
     * @param startPoses draw the start poses as outlines while a run shows robots
     */
    public record Options(boolean beams, boolean trail, boolean grid, boolean startPoses) {
        /** @return everything on */
        public static Options all() {
            return new Options(true, true, true, true);
        }
    }

    /**
     * The editor's state over the picture.
     *
     * @param selection selected items
     * @param band rubber band x1, y1, x2, y2 mm, or null
     * @param refused an item or area to outline in red, or null
     * @param trails per robot trails (x, y pairs, mm), or null
     */
    public record Overlay(Set<Item> selection, double[] band, double[] refused, List<float[]> trails) {
        /** Nothing over the picture. */
        public static final Overlay NONE = new Overlay(Set.of(), null, null, null);
    }

    private ArenaRenderer() {
    }

    /**
     * Draw it all.
     *
     * @param g where to draw
     * @param view the mm to px mapping
     * @param w width of the area, px
     * @param h height of the area, px
     * @param arena the arena (as edited)
     * @param snapshot the run's latest snapshot, or null to draw the start poses
     * @param overlay selection and the like
     * @param options what to show
     */
    public static void draw(Graphics2D g, ViewTransform view, int w, int h, Arena arena, Snapshot snapshot,
            Overlay overlay, Options options) {
        drawStatic(g, view, w, h, arena, options);
        drawDynamic(g, view, arena, snapshot, overlay, options);
    }

    /**
     * What does not move during a run: floor, grid, regions, lamps and walls. The view caches
     * this layer in an image and redraws it only when the arena or the zoom changes.
     */
    public static void drawStatic(Graphics2D g, ViewTransform view, int w, int h, Arena arena, Options options) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        g.setColor(OUTSIDE);
        g.fill(new Rectangle2D.Double(0, 0, w, h));
        Rectangle2D floor = new Rectangle2D.Double(view.sx(0), view.sy(arena.height()), view.len(arena.width()),
                view.len(arena.height()));
        g.setColor(FLOOR);
        g.fill(floor);
        if (options.grid()) {
            drawGrid(g, view, arena);
        }
        for (Region r : arena.regions()) {
            drawRegion(g, view, r);
        }
        // The glow lights the floor only: the light does not leave the enclosure.
        java.awt.Shape clip = g.getClip();
        g.clip(floor);
        for (Light l : arena.lights()) {
            drawLightGlow(g, view, l);
        }
        g.setClip(clip);
        for (int i = 0; i < arena.lights().size(); i++) {
            Light l = arena.lights().get(i);
            g.setColor(LAMP);
            g.fill(circle(view, l.x(), l.y(), l.radius()));
            g.setColor(LAMP.darker());
            g.setStroke(new BasicStroke(1f));
            g.draw(circle(view, l.x(), l.y(), l.radius()));
        }
        for (Wall wall : arena.walls()) {
            g.setColor(WALL);
            g.setStroke(new BasicStroke((float) StrictMath.max(1, view.len(wall.thickness())), BasicStroke.CAP_ROUND,
                    BasicStroke.JOIN_ROUND));
            g.draw(new Line2D.Double(view.sx(wall.x1()), view.sy(wall.y1()), view.sx(wall.x2()), view.sy(wall.y2())));
        }
    }

    /** What moves: caps, trails, robots, beams, and the editor's overlay. */
    public static void drawDynamic(Graphics2D g, ViewTransform view, Arena arena, Snapshot snapshot, Overlay overlay,
            Options options) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        if (snapshot == null || snapshot.caps().size() != arena.caps().size()) {
            for (Cap c : arena.caps()) {
                drawCap(g, view, c.x(), c.y(), c.radius(), false);
            }
        }
        if (snapshot != null) {
            for (CapView c : snapshot.caps()) {
                drawCap(g, view, c.x(), c.y(), c.radius(), c.held());
            }
        }
        if (options.trail() && overlay.trails() != null) {
            g.setColor(new Color(0x301E6FFF, true));
            g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            for (float[] t : overlay.trails()) {
                if (t.length >= 4) {
                    // Skip points less than a pixel from the last one drawn: a long trail at full speed
                    // has tens of thousands of points, nearly all on top of each other on screen.
                    Path2D.Float p = new Path2D.Float();
                    double lx = view.sx(t[0]);
                    double ly = view.sy(t[1]);
                    p.moveTo(lx, ly);
                    for (int k = 2; k < t.length; k += 2) {
                        double x = view.sx(t[k]);
                        double y = view.sy(t[k + 1]);
                        if (StrictMath.abs(x - lx) + StrictMath.abs(y - ly) >= 1.5 || k == t.length - 2) {
                            p.lineTo(x, y);
                            lx = x;
                            ly = y;
                        }
                    }
                    g.setColor(new Color(0x1E6FFF));
                    g.draw(p);
                }
            }
        }
        boolean live = snapshot != null && !snapshot.robots().isEmpty();
        for (int i = 0; i < arena.robots().size(); i++) {
            Pose p = arena.robots().get(i);
            if (!live) {
                drawRobot(g, view, arena.robotType(i), p.x(), p.y(), p.headingDeg(), null, null, false, 0);
            } else if (options.startPoses()) {
                drawStartGhost(g, view, p, arena.robotType(i).body().radiusMm());
            }
        }
        if (live) {
            for (RobotView r : snapshot.robots()) {
                drawRobot(g, view, r.type(), r.x(), r.y(), r.headingDeg(), r.gripper(),
                        options.beams() ? r.proximity() : null, true,
                        r.leds());
            }
        }
        drawOverlay(g, view, arena, overlay);
    }

    private static void drawGrid(Graphics2D g, ViewTransform view, Arena arena) {
        if (view.len(100) < 12) {
            return;
        }
        g.setColor(new Color(0xE4DFD2));
        g.setStroke(new BasicStroke(1f));
        for (double x = 100; x < arena.width(); x += 100) {
            g.draw(new Line2D.Double(view.sx(x), view.sy(0), view.sx(x), view.sy(arena.height())));
        }
        for (double y = 100; y < arena.height(); y += 100) {
            g.draw(new Line2D.Double(view.sx(0), view.sy(y), view.sx(arena.width()), view.sy(y)));
        }
    }

    private static void drawRegion(Graphics2D g, ViewTransform view, Region r) {
        Stroke old = g.getStroke();
        g.setColor(new Color(0x8090A0));
        g.setStroke(new BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {4f, 4f}, 0f));
        g.draw(new Rectangle2D.Double(view.sx(r.x1()), view.sy(r.y2()), view.len(r.x2() - r.x1()),
                view.len(r.y2() - r.y1())));
        g.setStroke(old);
        if (view.len(r.x2() - r.x1()) > 60) {
            g.setFont(g.getFont().deriveFont(Font.PLAIN, 10f));
            g.drawString(r.name(), (float) view.sx(r.x1()) + 3, (float) view.sy(r.y2()) + 11);
        }
    }

    private static void drawLightGlow(Graphics2D g, ViewTransform view, Light l) {
        float radius = (float) StrictMath.max(1, view.len(l.range()));
        float alpha = (float) StrictMath.min(0.55, 0.35 * l.intensity());
        RadialGradientPaint paint = new RadialGradientPaint((float) view.sx(l.x()), (float) view.sy(l.y()), radius,
                new float[] {0f, 1f}, new Color[] {new Color(1f, 0.85f, 0.2f, alpha), new Color(1f, 0.85f, 0.2f, 0f)},
                MultipleGradientPaint.CycleMethod.NO_CYCLE);
        g.setPaint(paint);
        if (l.isDirectional()) {
            g.fill(new Arc2D.Double(view.sx(l.x()) - radius, view.sy(l.y()) - radius, 2 * radius, 2 * radius,
                    l.directionDeg() - l.spreadDeg() / 2, l.spreadDeg(), Arc2D.PIE));
        } else {
            g.fill(new Ellipse2D.Double(view.sx(l.x()) - radius, view.sy(l.y()) - radius, 2 * radius, 2 * radius));
        }
    }

    private static void drawCap(Graphics2D g, ViewTransform view, double x, double y, double r, boolean held) {
        Ellipse2D c = circle(view, x, y, r);
        g.setColor(CAP);
        g.fill(c);
        g.setColor(held ? Color.WHITE : CAP.darker());
        g.setStroke(new BasicStroke(held ? 2f : 1f));
        g.draw(c);
    }

    private static void drawStartGhost(Graphics2D g, ViewTransform view, Pose p, double radius) {
        g.setColor(new Color(0x802E8B57, true));
        g.setStroke(new BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {3f, 3f}, 0f));
        g.draw(circle(view, p.x(), p.y(), radius));
    }

    /**
     * Draws a robot: body, wheels, heading, gripper turret, its two LEDs (bit 0, bit 1 of {@code leds}), optional
     * beams.
     */
    static void drawRobot(Graphics2D g, ViewTransform view, RobotType type, double x, double y, double headingDeg,
            GripperView gripper, int[] beams, boolean live, int leds) {
        double r = type.body().radiusMm();
        double h = StrictMath.toRadians(headingDeg);
        double cos = StrictMath.cos(h);
        double sin = StrictMath.sin(h);
        if (beams != null) {
            int max = type.proximity().maxReading();
            for (int i = 0; i < type.sensorCount() && i < beams.length; i++) {
                RobotType.Sensor s = type.sensor(i);
                double sx = x + s.xMm() * cos - s.yMm() * sin;
                double sy = y + s.xMm() * sin + s.yMm() * cos;
                double a = h + StrictMath.toRadians(s.headingDeg());
                double v = StrictMath.min(max, StrictMath.max(0, beams[i])) / (double) max;
                double len = 50;
                g.setColor(new Color(1f, 0.1f, 0.1f, (float) (0.15 + 0.7 * v)));
                g.setStroke(new BasicStroke((float) StrictMath.max(1, view.len(2))));
                g.draw(new Line2D.Double(view.sx(sx), view.sy(sy), view.sx(sx + len * StrictMath.cos(a)),
                        view.sy(sy + len * StrictMath.sin(a))));
            }
        }
        // Wheels: two dark bars on the sides.
        g.setColor(new Color(0x202020));
        g.setStroke(new BasicStroke((float) StrictMath.max(1, view.len(6)), BasicStroke.CAP_BUTT,
                BasicStroke.JOIN_MITER));
        for (int side = -1; side <= 1; side += 2) {
            // Drawn just inside the body's edge (the Khepera's: 24 mm from the centre).
            double wx = x - side * (r - 3.5) * sin;
            double wy = y + side * (r - 3.5) * cos;
            g.draw(new Line2D.Double(view.sx(wx - 10 * cos), view.sy(wy - 10 * sin), view.sx(wx + 10 * cos),
                    view.sy(wy + 10 * sin)));
        }
        Ellipse2D body = circle(view, x, y, r);
        g.setColor(live ? ROBOT : new Color(0x6FBF8F));
        g.fill(body);
        g.setColor(ROBOT.darker().darker());
        g.setStroke(new BasicStroke(1.5f));
        g.draw(body);
        if (gripper != null) {
            drawGripperOnRobot(g, view, x, y, cos, sin, gripper);
        }
        if (live) {
            // The two LEDs on the top of the robot, behind the centre: lit yellow, off dark.
            for (int i = 0; i < 2; i++) {
                double lx = -16;
                double ly = i == 0 ? 6 : -6;
                g.setColor((leds >> i & 1) != 0 ? LED_ON : LED_OFF);
                g.fill(circle(view, x + lx * cos - ly * sin, y + lx * sin + ly * cos, 3));
            }
        }
        // Heading: a line from the centre to the front, and a notch.
        g.setColor(Color.WHITE);
        g.setStroke(new BasicStroke((float) StrictMath.max(1.5, view.len(3)), BasicStroke.CAP_ROUND,
                BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(view.sx(x), view.sy(y), view.sx(x + r * 0.85 * cos), view.sy(y + r * 0.85 * sin)));
    }

    private static void drawGripperOnRobot(Graphics2D g, ViewTransform view, double x, double y, double cos, double sin,
            GripperView gv) {
        // Arm: from the body's front; the lower the arm, the farther ahead its fingers reach on the floor.
        double lowered = StrictMath.max(0, StrictMath.min(1, (gv.armPosition() - GripperTurret.ARM_UP)
                / (double) (GripperTurret.ARM_DOWN - GripperTurret.ARM_UP)));
        double reach = 27.5 + 4 + 14 * lowered;
        double spread = gv.fingers() == GripperState.OPEN ? 9 : 3;
        g.setColor(new Color(0x505A66));
        g.setStroke(new BasicStroke((float) StrictMath.max(1, view.len(3)), BasicStroke.CAP_ROUND,
                BasicStroke.JOIN_ROUND));
        for (int side = -1; side <= 1; side += 2) {
            double bx = x + 20 * cos - side * spread * sin;
            double by = y + 20 * sin + side * spread * cos;
            double ex = x + reach * cos - side * spread * sin;
            double ey = y + reach * sin + side * spread * cos;
            g.draw(new Line2D.Double(view.sx(bx), view.sy(by), view.sx(ex), view.sy(ey)));
        }
        if (gv.objectPresent()) {
            g.setColor(new Color(0xFF3030));
            g.fill(circle(view, x + (reach - 3) * cos, y + (reach - 3) * sin, 2.5));
        }
    }

    private static void drawOverlay(Graphics2D g, ViewTransform view, Arena arena, Overlay o) {
        g.setColor(SELECTION);
        for (Item it : o.selection()) {
            if (!EditorModel.exists(arena, it)) {
                continue;
            }
            g.setStroke(new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND, 10f,
                    new float[] {5f, 3f}, 0f));
            switch (it.kind()) {
                case ROBOT -> {
                    Pose p = arena.robots().get(it.index());
                    g.draw(circle(view, p.x(), p.y(), arena.robotType(it.index()).body().radiusMm() + 4));
                    double hx = p.x() + HEADING_HANDLE_MM * StrictMath.cos(StrictMath.toRadians(p.headingDeg()));
                    double hy = p.y() + HEADING_HANDLE_MM * StrictMath.sin(StrictMath.toRadians(p.headingDeg()));
                    g.draw(new Line2D.Double(view.sx(p.x()), view.sy(p.y()), view.sx(hx), view.sy(hy)));
                    handle(g, view, hx, hy);
                }
                case WALL -> {
                    Wall w = arena.walls().get(it.index());
                    g.setStroke(new BasicStroke((float) StrictMath.max(3, view.len(w.thickness()) + 4),
                            BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
                    g.setColor(new Color(0x601E6FFF, true));
                    g.draw(new Line2D.Double(view.sx(w.x1()), view.sy(w.y1()), view.sx(w.x2()), view.sy(w.y2())));
                    g.setColor(SELECTION);
                    handle(g, view, w.x1(), w.y1());
                    handle(g, view, w.x2(), w.y2());
                }
                case LIGHT -> {
                    Light l = arena.lights().get(it.index());
                    g.draw(circle(view, l.x(), l.y(), l.radius() + 5));
                }
                case CAP -> {
                    Cap c = arena.caps().get(it.index());
                    g.draw(circle(view, c.x(), c.y(), c.radius() + 4));
                }
            }
        }
        if (o.band() != null) {
            double[] b = o.band();
            Rectangle2D r = new Rectangle2D.Double(view.sx(StrictMath.min(b[0], b[2])),
                    view.sy(StrictMath.max(b[1], b[3])),
                    view.len(StrictMath.abs(b[2] - b[0])), view.len(StrictMath.abs(b[3] - b[1])));
            g.setComposite(AlphaComposite.getInstance(AlphaComposite.SRC_OVER, 0.15f));
            g.fill(r);
            g.setComposite(AlphaComposite.SrcOver);
            g.setStroke(new BasicStroke(1f));
            g.draw(r);
        }
        if (o.refused() != null) {
            double[] b = o.refused();
            g.setColor(REFUSED);
            g.setStroke(new BasicStroke(3f));
            g.draw(circle(view, b[0], b[1], b.length > 2 ? b[2] : 30));
        }
    }

    private static void handle(Graphics2D g, ViewTransform view, double x, double y) {
        Rectangle2D r = new Rectangle2D.Double(view.sx(x) - HANDLE_PX / 2, view.sy(y) - HANDLE_PX / 2,
                HANDLE_PX, HANDLE_PX);
        g.setColor(Color.WHITE);
        g.fill(r);
        g.setColor(SELECTION);
        g.setStroke(new BasicStroke(1.5f));
        g.draw(r);
    }

    private static Ellipse2D circle(ViewTransform view, double x, double y, double r) {
        return new Ellipse2D.Double(view.sx(x - r), view.sy(y + r), view.len(2 * r), view.len(2 * r));
    }
}
