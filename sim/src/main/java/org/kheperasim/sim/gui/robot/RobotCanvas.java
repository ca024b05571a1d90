package org.kheperasim.sim.gui.robot;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.geom.Arc2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.function.Consumer;
import javax.swing.JComponent;
import org.kheperasim.sim.engine.robot.RobotType;

/**
 * The robot drawn to scale on a millimetre grid, seen from above with its front up: the body, the
 * wheels and the wheel base, and every sensor's beam as a cone out to the response's range and
 * its widest beam angle. Drag a sensor's mount (the dot) to move it over the body, or the handle
 * at its beam's tip to turn it; a click chooses a sensor. A refused drag leaves the robot as it was
 * and says why.
 */
final class RobotCanvas extends JComponent {
    private static final double GRID_MM = 10;
    private static final double MARGIN_MM = 8;
    private static final int HIT_PX = 8;
    private static final double MOUNT_STEP_MM = 0.5;
    private static final Color BEAM = new Color(255, 170, 0, 60);
    private static final Color BEAM_CHOSEN = new Color(230, 60, 20, 90);

    private final RobotDraft draft;
    private final Consumer<String> refusal;
    private int dragging = -1;
    private boolean draggingTip;

    /** @param draft the robot drawn and edited @param refusal told why a drag was refused, or null when it was not */
    RobotCanvas(RobotDraft draft, Consumer<String> refusal) {
        this.draft = draft;
        this.refusal = refusal;
        setName("robotCanvas");
        setPreferredSize(new Dimension(520, 520));
        setBackground(Color.WHITE);
        setOpaque(true);
        setToolTipText("drag a sensor's dot to move it, the handle at its beam's tip to turn it");
        draft.onChange(this::repaint);
        MouseAdapter m = new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                pressed(e.getX(), e.getY());
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                dragged(e.getX(), e.getY());
            }

            @Override
            public void mouseReleased(MouseEvent e) {
                dragging = -1;
            }
        };
        addMouseListener(m);
        addMouseMotionListener(m);
    }

    /** @return the distance from the centre that the drawing must show, mm */
    private double extentMm() {
        RobotType t = draft.type();
        return StrictMath.max(t.body().radiusMm(), t.sensorReachMm() + t.proximity().response().rangeMm()) + MARGIN_MM;
    }

    /** @return pixels per mm */
    double scale() {
        return StrictMath.max(1e-3, (StrictMath.min(getWidth(), getHeight()) - 20) / (2 * extentMm()));
    }

    /** @param x mm forward @param y mm left @return where that is on the canvas, px */
    Point2D toScreen(double x, double y) {
        double s = scale();
        return new Point2D.Double(getWidth() / 2.0 - y * s, getHeight() / 2.0 - x * s);
    }

    /** @param px a canvas point @return the robot-frame point under it, mm (x forward, y left) */
    Point2D toRobot(double px, double py) {
        double s = scale();
        return new Point2D.Double((getHeight() / 2.0 - py) / s, (getWidth() / 2.0 - px) / s);
    }

    /** @param i a sensor @return its beam's tip (the heading handle) on the canvas, px */
    Point2D tip(int i) {
        RobotType.Sensor s = draft.type().sensor(i);
        double range = draft.type().proximity().response().rangeMm();
        double h = StrictMath.toRadians(s.headingDeg());
        return toScreen(s.xMm() + range * StrictMath.cos(h), s.yMm() + range * StrictMath.sin(h));
    }

    /** @param i a sensor @return its mount on the canvas, px */
    Point2D mount(int i) {
        RobotType.Sensor s = draft.type().sensor(i);
        return toScreen(s.xMm(), s.yMm());
    }

    private void pressed(int px, int py) {
        dragging = -1;
        RobotType t = draft.type();
        for (int pass = 0; pass < 2 && dragging < 0; pass++) {
            for (int i = 0; i < t.sensorCount(); i++) {
                Point2D p = pass == 0 ? tip(i) : mount(i);
                if (p.distance(px, py) <= HIT_PX) {
                    dragging = i;
                    draggingTip = pass == 0;
                    break;
                }
            }
        }
        if (dragging >= 0) {
            draft.select(dragging);
        }
    }

    private void dragged(int px, int py) {
        if (dragging < 0) {
            return;
        }
        Point2D p = toRobot(px, py);
        RobotType.Sensor s = draft.type().sensor(dragging);
        String why;
        if (draggingTip) {
            double deg = StrictMath.toDegrees(StrictMath.atan2(p.getY() - s.yMm(), p.getX() - s.xMm()));
            why = draft.turnSensor(dragging, StrictMath.rint(deg));
        } else {
            double x = StrictMath.rint(p.getX() / MOUNT_STEP_MM) * MOUNT_STEP_MM;
            double y = StrictMath.rint(p.getY() / MOUNT_STEP_MM) * MOUNT_STEP_MM;
            double r = draft.type().body().radiusMm();
            double at = StrictMath.hypot(x, y);
            if (at > r) { // kept on the body: slid along its edge
                x = towardZero(x * r / at);
                y = towardZero(y * r / at);
            }
            why = draft.moveSensor(dragging, x, y);
        }
        refusal.accept(why);
    }

    /** @param v mm @return v on the mount grid, rounded towards 0 (so within the body) */
    private static double towardZero(double v) {
        double k = StrictMath.floor(StrictMath.abs(v) / MOUNT_STEP_MM) * MOUNT_STEP_MM;
        return v < 0 ? -k : k;
    }

    @Override
    protected void paintComponent(Graphics g0) {
        Graphics2D g = (Graphics2D) g0.create();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(getBackground());
        g.fillRect(0, 0, getWidth(), getHeight());
        RobotType t = draft.type();
        grid(g);
        double s = scale();
        double r = t.body().radiusMm();
        Point2D c = toScreen(0, 0);
        g.setColor(new Color(235, 240, 250));
        g.fill(new Ellipse2D.Double(c.getX() - r * s, c.getY() - r * s, 2 * r * s, 2 * r * s));
        g.setColor(new Color(40, 60, 120));
        g.setStroke(new BasicStroke(2f));
        g.draw(new Ellipse2D.Double(c.getX() - r * s, c.getY() - r * s, 2 * r * s, 2 * r * s));
        Point2D front = toScreen(r, 0);
        g.draw(new Line2D.Double(c, front));
        wheels(g, t, s);
        for (int i = 0; i < t.sensorCount(); i++) {
            beam(g, t, i, s);
        }
        g.setColor(Color.DARK_GRAY);
        g.setFont(getFont().deriveFont(Font.PLAIN, 11f));
        g.drawString(String.format(java.util.Locale.ROOT,
                "%s: body radius %s mm, wheel base %s mm; grid %s mm; front up",
                t.name(), RobotChecks.num(r), RobotChecks.num(t.drive().wheelBaseMm()),
                RobotChecks.num(GRID_MM)), 6, 14);
        RobotType.Sensor c0 = t.sensor(draft.selected());
        g.setColor(new Color(200, 40, 10));
        g.drawString(String.format(java.util.Locale.ROOT, "sensor %d %s at (%s, %s) mm, heading %s deg",
                draft.selected(),
                c0.name(), RobotChecks.num(c0.xMm()), RobotChecks.num(c0.yMm()),
                RobotChecks.num(c0.headingDeg())), 6, 28);
        g.dispose();
    }

    private void grid(Graphics2D g) {
        double ext = extentMm() + GRID_MM * 3;
        for (double v = -StrictMath.floor(ext / GRID_MM) * GRID_MM; v <= ext; v += GRID_MM) {
            boolean major = StrictMath.abs(StrictMath.IEEEremainder(v, 5 * GRID_MM)) < 1e-9;
            g.setColor(v == 0 ? new Color(170, 170, 200) : major ? new Color(215, 215, 225) : new Color(238, 238, 242));
            g.draw(new Line2D.Double(toScreen(v, -ext), toScreen(v, ext)));
            g.draw(new Line2D.Double(toScreen(-ext, v), toScreen(ext, v)));
        }
    }

    private void wheels(Graphics2D g, RobotType t, double s) {
        double half = t.drive().wheelBaseMm() / 2;
        double len = t.body().radiusMm() * 0.7;
        double w = 3;
        g.setColor(new Color(60, 60, 60));
        for (double y : new double[] {half, -half}) {
            Point2D a = toScreen(len / 2, y + w / 2);
            g.fill(new Rectangle2D.Double(a.getX(), a.getY(), w * s, len * s));
        }
        Point2D l = toScreen(0, half);
        Point2D rgt = toScreen(0, -half);
        g.setStroke(new BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 1f, new float[] {4f, 3f}, 0f));
        g.draw(new Line2D.Double(l, rgt));
        g.setStroke(new BasicStroke(1f));
    }

    private void beam(Graphics2D g, RobotType t, int i, double s) {
        RobotType.Sensor sensor = t.sensor(i);
        double[] angles = t.proximity().response().anglesDeg();
        double half = angles[angles.length - 1];
        double range = t.proximity().response().rangeMm();
        Point2D m = mount(i);
        // Robot headings count counter-clockwise from ahead (up on screen); Arc2D's from the screen's +x.
        double start = sensor.headingDeg() + 90 - half;
        Arc2D cone = new Arc2D.Double(m.getX() - range * s, m.getY() - range * s, 2 * range * s, 2 * range * s, start,
                2 * half, Arc2D.PIE);
        boolean chosen = i == draft.selected();
        g.setColor(chosen ? BEAM_CHOSEN : BEAM);
        g.fill(cone);
        g.setColor(chosen ? new Color(200, 40, 10) : new Color(200, 130, 0));
        Point2D tip = tip(i);
        g.draw(new Line2D.Double(m, tip));
        g.fill(new Ellipse2D.Double(tip.getX() - 4, tip.getY() - 4, 8, 8));
        g.setColor(chosen ? new Color(200, 40, 10) : new Color(20, 90, 40));
        g.fill(new Ellipse2D.Double(m.getX() - 4, m.getY() - 4, 8, 8));
        g.setColor(Color.BLACK);
        // The index beyond the tip, along the beam (names of neighbours would overlap; the chosen one is named above).
        double h = StrictMath.toRadians(sensor.headingDeg());
        String label = Integer.toString(i);
        int w = g.getFontMetrics().stringWidth(label);
        g.drawString(label, (float) (tip.getX() - 12 * StrictMath.sin(h) - w / 2.0),
                (float) (tip.getY() - 12 * StrictMath.cos(h) + 4));
    }
}
