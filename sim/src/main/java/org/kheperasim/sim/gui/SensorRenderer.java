package org.kheperasim.sim.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.awt.geom.RoundRectangle2D;
import java.util.Locale;
import org.kheperasim.api.GripperState;
import org.kheperasim.sim.engine.robot.GripperTurret;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.view.GripperView;
import org.kheperasim.sim.engine.view.RobotView;

/**
 * Draws the sensor panel of the paper's Figure 2 into a {@link Graphics2D}: a top view of the
 * robot with its 8 proximity values (red bars, 0..1023, higher = nearer) and 8 ambient-light
 * values (yellow bars, 0..1023, lower = brighter) beside each sensor; the gripper's arm, fingers
 * and object sensor as icons; wheel speeds and encoder counts.
 */
public final class SensorRenderer {
    /** Proximity bars. */
    public static final Color PROX = new Color(0xD43C3C);
    /** Light bars. */
    public static final Color LIGHT = new Color(0xE0A800);
    /** Height of the drawing for a given width, px. */
    static final int ROBOT_AREA = 260;
    /** The drawing's size at scale 1, px: it is scaled as a whole to the panel, text included. */
    static final int BASE_WIDTH = 330;
    static final int BASE_HEIGHT = ROBOT_AREA + 150;
    /** Largest scale: beyond it the drawing only gets emptier. */
    static final double MAX_SCALE = 2.4;

    private SensorRenderer() {
    }

    /** @return the height the panel wants at scale 1, px */
    public static int preferredHeight() {
        return BASE_HEIGHT;
    }

    /**
     * @param w the panel's width, px
     * @param h its height, px
     * @return the scale the drawing takes there: as large as fits, up to {@link #MAX_SCALE}
     */
    static double scale(int w, int h) {
        return StrictMath.max(0.1,
                StrictMath.min(MAX_SCALE, StrictMath.min(w / (double) BASE_WIDTH, h / (double) BASE_HEIGHT)));
    }

    /**
     * @param g where to draw
     * @param w width, px
     * @param h height, px
     * @param r the robot, or null before a run
     */
    public static void draw(Graphics2D g, int w, int h, RobotView r) {
        draw(g, w, h, r, null);
    }

    /**
     * As {@link #draw(Graphics2D, int, int, RobotView)}, telling the run's state where the
     * controller's own would mislead (a running controller in a paused run shows "paused").
     *
     * @param runState the run's state (running, paused, stopped, ...), or null
     */
    public static void draw(Graphics2D g, int w, int h, RobotView r, String runState) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_FRACTIONALMETRICS, RenderingHints.VALUE_FRACTIONALMETRICS_ON);
        g.setColor(new Color(0xFAFAFA));
        g.fill(new Rectangle2D.Double(0, 0, w, h));
        // The whole drawing, text included, scales with the panel: readable on a small window, larger on a large
        // screen.
        double scale = scale(w, h);
        g.translate((w - BASE_WIDTH * scale) / 2, 0);
        g.scale(scale, scale);
        drawAtBase(g, BASE_WIDTH, r, runState);
    }

    private static void drawAtBase(Graphics2D g, int w, RobotView r, String runState) {
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        double cx = w / 2.0;
        double cy = ROBOT_AREA / 2.0 + 12;
        double body = StrictMath.min(w, ROBOT_AREA) * 0.20;
        // The robot, seen from above, facing up the page.
        g.setColor(new Color(0x2E8B57));
        g.fill(new Ellipse2D.Double(cx - body, cy - body, 2 * body, 2 * body));
        g.setColor(Color.WHITE);
        g.setStroke(new BasicStroke(3f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(cx, cy, cx, cy - body * 0.85));
        g.setColor(new Color(0x202020));
        g.setStroke(new BasicStroke(5f));
        g.draw(new Line2D.Double(cx - body - 1, cy - 8, cx - body - 1, cy + 8));
        g.draw(new Line2D.Double(cx + body + 1, cy - 8, cx + body + 1, cy + 8));
        FontMetrics fm = g.getFontMetrics();
        RobotType type = r == null ? RobotTypes.KHEPERA1 : r.type();
        for (int index = 0; index < type.sensorCount(); index++) {
            RobotType.Sensor s = type.sensor(index);
            // Sensor position on the body: x forward, y left in the robot's frame; page up = forward.
            double ang = StrictMath.atan2(s.yMm(), s.xMm());
            double px = cx - body * StrictMath.sin(ang);
            double py = cy - body * StrictMath.cos(ang);
            g.setColor(new Color(0x202020));
            g.fill(new Ellipse2D.Double(px - 3, py - 3, 6, 6));
            int prox = r == null || index >= r.sensorCount() ? 0 : r.proximity(index);
            int light = r == null || index >= r.sensorCount() ? 0 : r.light(index);
            double lx = cx - (body + 50) * StrictMath.sin(ang);
            double ly = cy - (body + 50) * StrictMath.cos(ang);
            // Labels need room: the back sensors sit side by side, spread them apart.
            // (The bundled robots list their sensors in the Khepera's order: 2 and 3 ahead, 6 and 7 behind.)
            if (index == 2) {
                lx -= 34;
                ly -= 6;
            } else if (index == 3) {
                lx += 34;
                ly -= 6;
            } else if (index == 6) {
                lx += 36;
                ly = cy + body + 32;
            } else if (index == 7) {
                lx -= 36;
                ly = cy + body + 32;
            }
            drawReading(g, fm, lx, ly, index, prox, light, type.proximity().maxReading(), r != null);
        }
        double y = ROBOT_AREA + 10;
        GripperView gv = r == null ? null : r.gripper();
        double icon = 46;
        double gap = (w - 3 * icon) / 4.0;
        drawArmIcon(g, gap, y, icon, gv);
        drawFingersIcon(g, 2 * gap + icon, y, icon, gv);
        drawObjectIcon(g, 3 * gap + 2 * icon, y, icon, gv);
        g.setColor(new Color(0x333333));
        y += icon + 16;
        caption(g, fm, gap + icon / 2, y, "arm " + (gv == null ? "-" : armText(gv)));
        caption(g, fm, 2 * gap + 1.5 * icon, y,
                "fingers " + (gv == null ? "-" : gv.fingers().name().toLowerCase(Locale.ROOT)));
        caption(g, fm, 3 * gap + 2.5 * icon, y,
                gv == null ? "object -" : gv.objectPresent() ? "object: yes (" + gv.resistivity() + ")" : "object: no");
        y += 22;
        g.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        g.setColor(Color.BLACK);
        if (r != null) {
            // The robot's own speed unit: 8 mm/s on a Khepera, 0.1288 mm/s (one step a second) on an e-puck.
            g.drawString(String.format(Locale.ROOT, "speed   L %4d   R %4d  (units of %s mm/s)", r.speedLeft(),
                    r.speedRight(), new java.math.BigDecimal(Double.toString(
                            r.type().drive().mmPerSecondPerUnit())).stripTrailingZeros()
                                    .toPlainString()), 10, (float) y);
            g.drawString(String.format(Locale.ROOT, "encoder L %7d R %7d  pulses", r.encoderLeft(), r.encoderRight()),
                    10, (float) y + 16);
            g.drawString(String.format(Locale.ROOT, "pose (%.1f, %.1f) mm  %.1f deg  robot %d", r.x(),
                    r.y(), r.headingDeg(),
                    r.id()), 10, (float) y + 32);
            g.drawString("contact " + r.contact().name().toLowerCase(Locale.ROOT) + "  collisions " + r.collisions()
                    + "  " + ("running".equals(r.controller()) && runState != null ? runState : r.controller()), 10,
                    (float) y + 48);
        } else {
            g.drawString("no run yet: press Start", 10, (float) y);
        }
    }

    private static String armText(GripperView gv) {
        String pos = gv.armPosition() <= GripperTurret.ARM_UP + 5 ? "up"
                : gv.armPosition() >= GripperTurret.ARM_DOWN - 5 ? "down" : Integer.toString(gv.armPosition());
        return pos + (gv.armMoving() ? " (moving)" : "");
    }

    private static void caption(Graphics2D g, FontMetrics fm, double cx, double y, String text) {
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        g.drawString(text, (float) (cx - g.getFontMetrics().stringWidth(text) / 2.0), (float) y);
    }

    private static void drawReading(Graphics2D g, FontMetrics fm, double cx, double cy, int index, int prox,
            int light, int proxTop, boolean live) {
        double bw = 54;
        double bh = 6;
        double x0 = cx - bw / 2;
        g.setColor(new Color(0xE6E6E6));
        g.fill(new Rectangle2D.Double(x0, cy - 9, bw, bh));
        g.fill(new Rectangle2D.Double(x0, cy + 9, bw, bh));
        g.setColor(PROX);
        g.fill(new Rectangle2D.Double(x0, cy - 9, bw * clamp(prox, proxTop), bh));
        g.setColor(LIGHT);
        g.fill(new Rectangle2D.Double(x0, cy + 9, bw * clamp(light, 1023), bh));
        g.setColor(Color.BLACK);
        String t = live ? index + ": " + prox + " / " + light : index + ": - / -";
        g.drawString(t, (float) (cx - fm.stringWidth(t) / 2.0), (float) cy + 6);
    }

    /** @return a reading as a fraction of its scale's top (a Khepera's 1023, an e-puck's 4095) */
    private static double clamp(int v, int top) {
        return StrictMath.max(0, StrictMath.min(top, v)) / (double) top;
    }

    /** Side view of the arm: raised or lowered by its position. */
    private static void drawArmIcon(Graphics2D g, double x, double y, double s, GripperView gv) {
        frame(g, x, y, s);
        double lowered = gv == null ? 0 : StrictMath.max(0, StrictMath.min(1, (gv.armPosition() - GripperTurret.ARM_UP)
                / (double) (GripperTurret.ARM_DOWN - GripperTurret.ARM_UP)));
        double px = x + s * 0.25;
        double py = y + s * 0.35;
        double ang = StrictMath.toRadians(60 - 100 * lowered);
        double len = s * 0.6;
        g.setColor(new Color(0x777777));
        g.fill(new Rectangle2D.Double(x + 4, y + s * 0.35, s * 0.25, s * 0.45));
        g.setColor(gv != null && gv.armMoving() ? new Color(0xE07000) : new Color(0x305080));
        g.setStroke(new BasicStroke(4f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(px, py, px + len * StrictMath.cos(ang), py - len * StrictMath.sin(ang)));
        g.setColor(new Color(0x999999));
        g.setStroke(new BasicStroke(1f));
        g.draw(new Line2D.Double(x + 2, y + s * 0.85, x + s - 2, y + s * 0.85));
    }

    /** The fingers seen from the front: apart or together. */
    private static void drawFingersIcon(Graphics2D g, double x, double y, double s, GripperView gv) {
        frame(g, x, y, s);
        boolean open = gv == null || gv.fingers() == GripperState.OPEN;
        double spread = open ? s * 0.3 : s * 0.08;
        double cx = x + s / 2;
        g.setColor(new Color(0x305080));
        g.setStroke(new BasicStroke(5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(cx - spread, y + s * 0.2, cx - spread, y + s * 0.8));
        g.draw(new Line2D.Double(cx + spread, y + s * 0.2, cx + spread, y + s * 0.8));
        g.setStroke(new BasicStroke(3f));
        g.draw(new Line2D.Double(cx - s * 0.35, y + s * 0.2, cx + s * 0.35, y + s * 0.2));
    }

    /** The optical barrier between the fingers: a lit LED when something breaks it. */
    private static void drawObjectIcon(Graphics2D g, double x, double y, double s, GripperView gv) {
        frame(g, x, y, s);
        boolean present = gv != null && gv.objectPresent();
        Ellipse2D led = new Ellipse2D.Double(x + s * 0.3, y + s * 0.3, s * 0.4, s * 0.4);
        g.setColor(present ? new Color(0xFF3030) : new Color(0xDDDDDD));
        g.fill(led);
        g.setColor(Color.DARK_GRAY);
        g.setStroke(new BasicStroke(1.5f));
        g.draw(led);
    }

    private static void frame(Graphics2D g, double x, double y, double s) {
        RoundRectangle2D f = new RoundRectangle2D.Double(x, y, s, s, 8, 8);
        g.setColor(Color.WHITE);
        g.fill(f);
        g.setColor(new Color(0xB0B0B0));
        g.setStroke(new BasicStroke(1f));
        g.draw(f);
    }
}
