package org.kheperasim.sim.compare;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;

/** The picture of a {@link Divergence}: both odometry paths side by side on one scale, and the parting point. */
public final class PathPlot {
    private static final int SIZE = 640;
    private static final int MARGIN = 40;
    private static final Color REAL = new Color(0xd62728);
    private static final Color SIM = new Color(0x1f77b4);

    private PathPlot() {
    }

    /** @param d the divergence @param png where to write the picture */
    public static void write(Divergence d, Path png) throws IOException {
        double minX = 0;
        double maxX = 1;
        double minY = 0;
        double maxY = 1;
        for (double[][] path : new double[][][] {d.realPath(), d.simPath()}) {
            for (double[] p : path) {
                minX = StrictMath.min(minX, p[0]);
                maxX = StrictMath.max(maxX, p[0]);
                minY = StrictMath.min(minY, p[1]);
                maxY = StrictMath.max(maxY, p[1]);
            }
        }
        double scale = (SIZE - 2 * MARGIN) / StrictMath.max(maxX - minX, maxY - minY);
        BufferedImage img = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, SIZE, SIZE);
        g.setStroke(new BasicStroke(2f));
        double x0 = minX;
        double y0 = minY;
        int parted = -1;
        for (int k = 0; k < d.times().length; k++) {
            if (!Double.isNaN(d.partedAt()) && d.times()[k] >= d.partedAt() && parted < 0) {
                parted = k;
            }
        }
        Color[] colours = {REAL, SIM};
        double[][][] paths = {d.realPath(), d.simPath()};
        for (int p = 0; p < 2; p++) {
            g.setColor(colours[p]);
            for (int k = 1; k < paths[p].length; k++) {
                g.drawLine(px(paths[p][k - 1][0], x0, scale), py(paths[p][k - 1][1], y0, scale),
                        px(paths[p][k][0], x0, scale), py(paths[p][k][1], y0, scale));
            }
            if (parted >= 0) {
                g.drawOval(px(paths[p][parted][0], x0, scale) - 5, py(paths[p][parted][1], y0, scale) - 5, 10, 10);
            }
        }
        g.setColor(REAL);
        g.drawString("real run (odometry)", MARGIN, 20);
        g.setColor(SIM);
        g.drawString("simulation (odometry)", MARGIN + 160, 20);
        g.setColor(Color.DARK_GRAY);
        g.drawString(Double.isNaN(d.partedAt()) ? String.format(Locale.ROOT, "never %.0f mm apart", d.thresholdMm())
                : String.format(Locale.ROOT, "%.0f mm apart at %.2f s (rings)", d.thresholdMm(), d.partedAt()),
                MARGIN + 340, 20);
        g.dispose();
        org.kheperasim.sim.files.AtomicFiles.writePng(png, img);
    }

    private static int px(double x, double x0, double scale) {
        return MARGIN + (int) StrictMath.rint((x - x0) * scale);
    }

    private static int py(double y, double y0, double scale) {
        return SIZE - MARGIN - (int) StrictMath.rint((y - y0) * scale);
    }
}
