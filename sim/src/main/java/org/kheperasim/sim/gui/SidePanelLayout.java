package org.kheperasim.sim.gui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Dimension;
import java.awt.Insets;
import java.awt.LayoutManager;

/**
 * Places the sensor panel and the plot in the window's right-hand column: one above the other, or
 * side by side when that draws the sensor panel clearly larger, the plot keeping at least
 * {@link #PLOT_MIN_HEIGHT} × {@link #PLOT_MIN_WIDTH}. On a short window (900 × 600) they go side by
 * side, where stacked the sensor panel took the whole height and the plot vanished; on a tall one
 * they stack. The sensor panel draws itself at the scale its box allows (see {@link SensorRenderer}).
 */
final class SidePanelLayout implements LayoutManager {
    /** The plot never gets less than this, px. */
    static final int PLOT_MIN_HEIGHT = 170;
    static final int PLOT_MIN_WIDTH = 260;
    /** The plot's least share of a large column. */
    private static final double PLOT_SHARE = 0.3;
    /** Side by side only when it draws the sensor panel this much larger: a plot over time reads best wide. */
    private static final double SIDE_BY_SIDE_GAIN = 1.2;

    private final Component sensors;
    private final Component plot;

    SidePanelLayout(Component sensors, Component plot) {
        this.sensors = sensors;
        this.plot = plot;
    }

    /**
     * @param w the column's width, px
     * @param h its height, px
     * @return true when side by side draws the sensor panel clearly larger than stacked
     */
    static boolean sideBySide(int w, int h) {
        return sensorScale(w, h, true) > SIDE_BY_SIDE_GAIN * sensorScale(w, h, false);
    }

    /** @return the sensor panel's scale in a column of w × h, in one arrangement or the other */
    static double sensorScale(int w, int h, boolean sideBySide) {
        return sideBySide ? SensorRenderer.scale(w - plotWidth(w), h) : SensorRenderer.scale(w, h - plotHeight(h));
    }

    /** The plot's least height stacked, px: {@link #PLOT_MIN_HEIGHT}, or a share of a tall column. */
    private static int plotHeight(int h) {
        return StrictMath.max(PLOT_MIN_HEIGHT, (int) (PLOT_SHARE * h));
    }

    /** The plot's least width side by side, px. */
    private static int plotWidth(int w) {
        return StrictMath.max(PLOT_MIN_WIDTH, (int) (PLOT_SHARE * w));
    }

    @Override
    public void layoutContainer(Container parent) {
        Insets in = parent.getInsets();
        int w = parent.getWidth() - in.left - in.right;
        int h = parent.getHeight() - in.top - in.bottom;
        boolean side = sideBySide(w, h);
        double s = sensorScale(w, h, side);
        if (side) {
            int sw = (int) StrictMath.ceil(SensorRenderer.BASE_WIDTH * s);
            sensors.setBounds(in.left, in.top, sw, h);
            plot.setBounds(in.left + sw, in.top, w - sw, h);
        } else {
            // The vision strip, when shown, goes under the sensor panel without shrinking it.
            int strip = sensors instanceof SensorColumn c && c.strip().isVisible() ? VisionStrip.PREFERRED_HEIGHT : 0;
            int sh = StrictMath.min(h, (int) StrictMath.ceil(SensorRenderer.BASE_HEIGHT * s) + strip);
            sensors.setBounds(in.left, in.top, w, sh);
            plot.setBounds(in.left, in.top + sh, w, h - sh);
        }
    }

    @Override
    public Dimension preferredLayoutSize(Container parent) {
        return new Dimension(SensorRenderer.BASE_WIDTH, SensorRenderer.BASE_HEIGHT + PLOT_MIN_HEIGHT);
    }

    @Override
    public Dimension minimumLayoutSize(Container parent) {
        return new Dimension(260, 200);
    }

    @Override
    public void addLayoutComponent(String name, Component comp) {
    }

    @Override
    public void removeLayoutComponent(Component comp) {
    }
}
