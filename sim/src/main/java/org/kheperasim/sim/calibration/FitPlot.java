package org.kheperasim.sim.calibration;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.SampleTable;

/**
 * The picture of a {@link FitReport}: a panel per sensor, reading against the wall's gap with the
 * wall straight in front of the sensor and 30 degrees off it: the samples the fit saw (dots), the
 * held-out ones (red rings), the held-out fit (line) and its errors in the title.
 */
public final class FitPlot {
    private static final int PANEL_W = 320;
    private static final int PANEL_H = 240;
    private static final int MARGIN = 36;
    private static final Color[] ANGLE_COLOURS = {new Color(0x1f77b4), new Color(0x2ca02c)};
    private static final double[] OFF_AXIS_DEG = {0, 30};

    private FitPlot() {
    }

    /** @param report the report @param png where to write the picture */
    public static void write(FitReport report, Path png) throws IOException {
        SampleTable t = report.table();
        int n = t.sensors();
        int cols = 4;
        int rows = (n + cols - 1) / cols;
        BufferedImage img = new BufferedImage(cols * PANEL_W, rows * PANEL_H, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, img.getWidth(), img.getHeight());
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        for (int i = 0; i < n; i++) {
            panel(g, report, i, (i % cols) * PANEL_W, (i / cols) * PANEL_H);
        }
        g.dispose();
        org.kheperasim.sim.files.AtomicFiles.writePng(png, img);
    }

    private static void panel(Graphics2D g, FitReport r, int sensor, int x0, int y0) {
        SampleTable t = r.table();
        RobotType type = r.type();
        double maxGap = t.gapMm(t.blocks() - 1);
        int w = PANEL_W - 2 * MARGIN + 16;
        int h = PANEL_H - 2 * MARGIN;
        int left = x0 + MARGIN;
        int bottom = y0 + PANEL_H - MARGIN + 8;
        g.setColor(Color.LIGHT_GRAY);
        g.drawRect(left, bottom - h, w, h);
        g.setColor(Color.DARK_GRAY);
        FitReport.Errors e = r.sensors().get(sensor);
        g.drawString(String.format(Locale.ROOT, "%d %s  held-out median %.0f rms %.0f", sensor,
                type.sensor(sensor).name(),
                e.median(), e.rms()), left, y0 + 16);
        g.drawString("0", left - 10, bottom);
        g.drawString("1023", left - 30, bottom - h + 10);
        g.drawString(String.format(Locale.ROOT, "gap %.0f mm", maxGap), left + w - 60, bottom + 14);
        for (int a = 0; a < OFF_AXIS_DEG.length; a++) {
            // The wall straight in front of the sensor: it lies -heading degrees to the robot's right.
            double right = Math.IEEEremainder(-type.sensor(sensor).headingDeg() + OFF_AXIS_DEG[a], 360);
            int k = (int) StrictMath.floorMod((long) StrictMath.rint(right / (360.0 / t.angles())), t.angles());
            double rightDeg = t.objectRightDeg(k);
            g.setColor(ANGLE_COLOURS[a]);
            g.setStroke(new BasicStroke(1.5f));
            int px = -1;
            int py = -1;
            for (int s = 0; s <= 100; s++) {
                double gap = maxGap * s / 100;
                double v = r.heldOutFit().predict(type, sensor, gap, rightDeg);
                int x = left + (int) (w * gap / maxGap);
                int y = bottom - (int) (h * v / SampleTable.FULL_SCALE);
                if (px >= 0) {
                    g.drawLine(px, py, x, y);
                }
                px = x;
                py = y;
            }
            for (int b = 0; b < t.blocks(); b++) {
                int x = left + (int) (w * t.gapMm(b) / maxGap);
                int y = bottom - (int) (h * t.counts(b, k, sensor) / (double) SampleTable.FULL_SCALE);
                if (FitReport.heldOut(b)) {
                    g.setColor(Color.RED);
                    g.drawOval(x - 3, y - 3, 6, 6);
                } else {
                    g.setColor(ANGLE_COLOURS[a]);
                    g.fillOval(x - 2, y - 2, 5, 5);
                }
            }
            g.setColor(ANGLE_COLOURS[a]);
            g.drawString(String.format(Locale.ROOT, "wall %.0f deg off axis", OFF_AXIS_DEG[a]), left + w - 120,
                    bottom - h + 14 + 13 * a);
        }
    }
}
