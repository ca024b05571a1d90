package org.kheperasim.sim.gui.robot;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import javax.swing.JComponent;
import org.kheperasim.sim.engine.robot.Response;

/**
 * A proximity response drawn over distance: the reading at each beam angle of the response in
 * grey, the chosen angle in red, with labelled distance and reading axes.
 */
final class ResponsePlot extends JComponent {
    private static final int LEFT = 42;
    private static final int BOTTOM = 22;
    private static final int TOP = 8;
    private static final int RIGHT = 10;
    private static final int STEPS = 120;

    private Response response;
    private double angleDeg;
    private double maxReading = 1;

    ResponsePlot() {
        setName("responsePlot");
        setPreferredSize(new Dimension(260, 170));
    }

    /** @param r the response @param angle the chosen angle, degrees @param max the reading axis' top */
    void show(Response r, double angle, double max) {
        response = r;
        angleDeg = angle;
        maxReading = StrictMath.max(1, max);
        repaint();
    }

    @Override
    protected void paintComponent(Graphics g0) {
        Graphics2D g = (Graphics2D) g0.create();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, getWidth(), getHeight());
        if (response == null) {
            g.dispose();
            return;
        }
        int w = getWidth() - LEFT - RIGHT;
        int h = getHeight() - TOP - BOTTOM;
        double range = response.rangeMm();
        g.setColor(Color.GRAY);
        g.drawRect(LEFT, TOP, w, h);
        g.setFont(getFont().deriveFont(10f));
        for (int k = 0; k <= 4; k++) {
            double d = range * k / 4;
            int x = LEFT + (int) StrictMath.round(w * k / 4.0);
            g.setColor(new Color(230, 230, 230));
            g.drawLine(x, TOP, x, TOP + h);
            g.setColor(Color.DARK_GRAY);
            g.drawString(RobotChecks.num(StrictMath.rint(d)), x - 8, TOP + h + 12);
            double v = maxReading * k / 4;
            int y = TOP + h - (int) StrictMath.round(h * k / 4.0);
            g.drawString(RobotChecks.num(StrictMath.rint(v)), 2, y + 4);
        }
        g.drawString("mm", LEFT + w - 16, TOP + h + 21);
        double[] angles = response.anglesDeg();
        for (double a : angles) {
            g.setColor(new Color(150, 150, 150));
            g.setStroke(new BasicStroke(1f));
            g.draw(curve(a, w, h, range));
        }
        g.setColor(new Color(210, 30, 30));
        g.setStroke(new BasicStroke(2f));
        g.draw(curve(angleDeg, w, h, range));
        g.drawString(RobotChecks.num(angleDeg) + " deg", LEFT + w - 52, TOP + 12);
        g.setStroke(new BasicStroke(1f));
        g.draw(new Line2D.Double(LEFT, TOP + h, LEFT + w, TOP + h));
        g.dispose();
    }

    private Path2D curve(double angle, int w, int h, double range) {
        Path2D p = new Path2D.Double();
        for (int i = 0; i <= STEPS; i++) {
            double d = range * i / STEPS;
            double v = StrictMath.min(maxReading, response.valueAt(d, angle));
            double x = LEFT + w * (d / range);
            double y = TOP + h - h * (v / maxReading);
            if (i == 0) {
                p.moveTo(x, y);
            } else {
                p.lineTo(x, y);
            }
        }
        return p;
    }
}
