package org.kheperasim.sim.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.util.Locale;
import javax.swing.JComponent;

/**
 * Draws chosen channels of a robot's samples over a span of time, with a time axis in seconds and
 * a value axis in the quantity's units, both with labelled ticks, and a cursor line (the replay's
 * time). Knows nothing of Swing's controls: {@link PlotPanel} tells it what to draw.
 */
final class PlotCanvas extends JComponent {
    static final Color[] COLOURS = {
        new Color(0xE6194B), new Color(0x3CB44B), new Color(0x4363D8), new Color(0xF58231),
        new Color(0x911EB4), new Color(0x42D4F4), new Color(0xF032E6), new Color(0x9A6324),
    };
    private static final int LEFT = 46;
    private static final int BOTTOM = 26;
    private static final int TOP = 8;
    private static final int RIGHT = 8;

    /**
     * What to draw.
     *
     * @param data row 0 times, s; then one row per channel
     * @param labels each channel's label
     * @param colours each channel's colour index
     * @param from the span's start, s
     * @param to the span's end, s
     * @param fixedMax the value axis' top when fixed (sensors 0..1023), or NaN to fit the data
     * @param unit the value axis' title
     * @param cursor a time to mark, s, or NaN
     */
    record Plot(double[][] data, String[] labels, int[] colours, double from, double to, double fixedMax, String unit,
            double cursor) {
    }

    private Plot plot;

    /** @param p what to draw, or null for nothing */
    void show(Plot p) {
        plot = p;
        repaint();
    }

    /** @return what is drawn, or null */
    Plot plot() {
        return plot;
    }

    @Override
    protected void paintComponent(Graphics g) {
        paintPlot((Graphics2D) g, getWidth(), getHeight());
    }

    /** @param g where to draw @param w width, px @param h height, px */
    void paintPlot(Graphics2D g, int w, int h) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fill(new Rectangle2D.Double(0, 0, w, h));
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 10));
        Plot p = plot;
        if (p == null) {
            g.setColor(Color.GRAY);
            String none = "no run yet: Start one, or open a recording";
            if (g.getFontMetrics().stringWidth(none) > w - 8) {
                none = "no run yet";
            }
            g.drawString(none, StrictMath.max(4, (w - g.getFontMetrics().stringWidth(none)) / 2), h / 2);
            return;
        }
        double lo = 0;
        double hi = p.fixedMax();
        if (Double.isNaN(hi)) {
            lo = Double.POSITIVE_INFINITY;
            hi = Double.NEGATIVE_INFINITY;
            for (int c = 1; c < p.data().length; c++) {
                for (double v : p.data()[c]) {
                    lo = StrictMath.min(lo, v);
                    hi = StrictMath.max(hi, v);
                }
            }
            if (lo > hi) {
                lo = 0;
                hi = 1;
            }
            if (hi - lo < 1) {
                hi = lo + 1;
            }
        }
        double from = p.from();
        double to = StrictMath.max(p.to(), from + 1e-3);
        int ph = h - TOP - BOTTOM;
        FontMetrics fm = g.getFontMetrics();
        double ySpan = hi - lo;
        double yStep = niceStep(ySpan / StrictMath.max(2, ph / 28));
        // The value axis' labels decide the left margin (encoder counts run to seven digits and a sign).
        int left = LEFT;
        for (double v = StrictMath.ceil(lo / yStep) * yStep; v <= hi + 1e-9; v += yStep) {
            left = StrictMath.max(left, fm.stringWidth(label(v, yStep)) + 8);
        }
        int pw = w - left - RIGHT;
        for (double v = StrictMath.ceil(lo / yStep) * yStep; v <= hi + 1e-9; v += yStep) {
            double y = TOP + ph - (v - lo) / ySpan * ph;
            g.setColor(new Color(0xE4E4E4));
            g.draw(new Line2D.Double(left, y, left + pw, y));
            g.setColor(Color.DARK_GRAY);
            String s = label(v, yStep);
            g.drawString(s, left - 4 - fm.stringWidth(s), (float) (y + fm.getAscent() / 2.0 - 1));
        }
        // Time labels as wide as the span's digits need, spaced so that none overlaps the next.
        double xStep = niceStep((to - from) / StrictMath.max(2, pw / 70));
        int widest = StrictMath.max(fm.stringWidth(label(from, xStep)), fm.stringWidth(label(to, xStep)));
        if (widest + 12 > pw * xStep / (to - from)) {
            xStep = niceStep((to - from) * (widest + 12) / StrictMath.max(1, pw));
        }
        for (double t = StrictMath.ceil(from / xStep) * xStep; t <= to + 1e-9; t += xStep) {
            double x = left + (t - from) / (to - from) * pw;
            g.setColor(new Color(0xE4E4E4));
            g.draw(new Line2D.Double(x, TOP, x, TOP + ph));
            g.setColor(Color.DARK_GRAY);
            String s = label(t, xStep);
            // Kept inside the canvas: the last tick often falls on its right edge (a run shorter than the span).
            double lx = StrictMath.max(2, StrictMath.min(w - 4 - fm.stringWidth(s), x - fm.stringWidth(s) / 2.0));
            g.drawString(s, (float) lx, TOP + ph + fm.getAscent() + 2);
        }
        g.setColor(Color.GRAY);
        g.draw(new Rectangle2D.Double(left, TOP, pw, ph));
        g.drawString("t, s", left + pw - fm.stringWidth("t, s"), h - 2);
        // The axis' title, shortened (its note in brackets dropped) where it would run into "t, s".
        String unit = p.unit();
        if (fm.stringWidth(unit) > pw - fm.stringWidth("t, s") - 10 && unit.contains(" (")) {
            unit = unit.substring(0, unit.indexOf(" ("));
        }
        g.drawString(unit, left + 2, h - 2);
        double[] ts = p.data()[0];
        for (int c = 1; c < p.data().length; c++) {
            g.setColor(COLOURS[p.colours()[c - 1] % COLOURS.length]);
            g.setStroke(new BasicStroke(1.3f));
            Path2D.Double path = new Path2D.Double();
            for (int k = 0; k < ts.length; k++) {
                double x = left + (ts[k] - from) / (to - from) * pw;
                double y = TOP + ph - (StrictMath.max(lo, StrictMath.min(hi, p.data()[c][k])) - lo) / ySpan * ph;
                if (k == 0) {
                    path.moveTo(x, y);
                } else {
                    path.lineTo(x, y);
                }
            }
            g.draw(path);
        }
        if (!Double.isNaN(p.cursor()) && p.cursor() >= from && p.cursor() <= to) {
            double x = left + (p.cursor() - from) / (to - from) * pw;
            g.setColor(new Color(0x555555));
            g.setStroke(new BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f,
                    new float[] {3f, 3f}, 0f));
            g.draw(new Line2D.Double(x, TOP, x, TOP + ph));
        }
        if (ts.length == 0) {
            g.setColor(Color.GRAY);
            g.drawString("no samples in this span yet", left + 6, TOP + 14);
        }
    }

    /** @param raw a rough step @return 1, 2 or 5 times a power of ten, at least {@code raw} */
    static double niceStep(double raw) {
        if (!(raw > 0)) {
            return 1;
        }
        double mag = StrictMath.pow(10, StrictMath.floor(StrictMath.log10(raw)));
        double f = raw / mag;
        return (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * mag;
    }

    private static String label(double v, double step) {
        if (step >= 1) {
            return Long.toString(StrictMath.round(v));
        }
        int digits = (int) StrictMath.ceil(-StrictMath.log10(step));
        return String.format(Locale.ROOT, "%." + digits + "f", v);
    }
}
