package org.kheperasim.sim.gui;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.Graphics;
import java.awt.RenderingHints;
import java.awt.geom.Rectangle2D;
import java.util.Locale;
import java.util.function.Supplier;
import javax.swing.JComponent;
import org.kheperasim.sim.engine.view.VisionView;

/**
 * The image of the selected robot's K213 vision turret, as a strip of 64 grey cells, pixel 0 (the
 * left of the turret's view) on the left, with when it was taken; "not read" while the controller
 * has not read the turret. Drawing is {@link #draw}, testable into an image; this component only
 * hosts it for the latest snapshot's image.
 */
public final class VisionStrip extends JComponent {
    /** Height of the strip's drawing, px. */
    public static final int PREFERRED_HEIGHT = 38;
    private static final Color FRAME = new Color(0x555555);
    private static final Color TEXT = new Color(0x333333);

    private final Supplier<VisionView> image;

    /** @param image the image to show: the selected robot's in the latest snapshot, or null */
    public VisionStrip(Supplier<VisionView> image) {
        this.image = image;
        setName("visionStrip");
        setPreferredSize(new Dimension(330, PREFERRED_HEIGHT));
        setMinimumSize(new Dimension(140, PREFERRED_HEIGHT));
    }

    @Override
    protected void paintComponent(Graphics g) {
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            draw(g2, new Rectangle2D.Double(0, 0, getWidth(), getHeight()), image.get());
        } finally {
            g2.dispose();
        }
    }

    /**
     * Draw an image of the vision turret: a caption line, then 64 cells across the area's width, each
     * filled with its pixel's grey level.
     *
     * @param g where to draw
     * @param area the area to fill, px
     * @param view the image, or null when the turret has not been read
     */
    public static void draw(Graphics2D g, Rectangle2D area, VisionView view) {
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        FontMetrics fm = g.getFontMetrics();
        double top = area.getY() + fm.getHeight();
        double stripH = StrictMath.max(4, area.getHeight() - fm.getHeight() - 2);
        g.setColor(TEXT);
        String caption = view == null ? "vision turret: not read"
                : String.format(Locale.ROOT, "vision turret at %.2f s", view.takenNanos() / 1e9);
        g.drawString(caption, (float) area.getX() + 2, (float) (area.getY() + fm.getAscent()));
        if (view == null) {
            g.setColor(FRAME);
            g.draw(new Rectangle2D.Double(area.getX() + 1, top, area.getWidth() - 3, stripH));
            return;
        }
        int n = view.pixels().length;
        double cell = (area.getWidth() - 3) / n;
        for (int i = 0; i < n; i++) {
            int grey = StrictMath.max(0, StrictMath.min(255, view.pixel(i)));
            g.setColor(new Color(grey, grey, grey));
            double x0 = area.getX() + 1 + i * cell;
            g.fill(new Rectangle2D.Double(x0, top, StrictMath.ceil(cell), stripH));
        }
        g.setColor(FRAME);
        g.draw(new Rectangle2D.Double(area.getX() + 1, top, area.getWidth() - 3, stripH));
    }
}
