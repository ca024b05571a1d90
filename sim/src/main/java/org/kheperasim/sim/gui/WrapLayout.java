package org.kheperasim.sim.gui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Insets;

/**
 * A left-aligned flow that asks for the height of all its rows: the toolbar wraps onto a second
 * row on a narrow window instead of pushing its last controls (the controller box) off the edge.
 */
final class WrapLayout extends FlowLayout {
    WrapLayout() {
        super(FlowLayout.LEFT, 1, 1);
    }

    @Override
    public Dimension preferredLayoutSize(Container target) {
        return size(target, true);
    }

    @Override
    public Dimension minimumLayoutSize(Container target) {
        Dimension d = size(target, false);
        d.width -= getHgap() + 1;
        return d;
    }

    private Dimension size(Container target, boolean preferred) {
        synchronized (target.getTreeLock()) {
            // The width the toolbar has: its own once laid out, else its parent's (the first layout).
            int width = target.getWidth();
            Container parent = target.getParent();
            if (width == 0 && parent != null) {
                width = parent.getWidth();
            }
            if (width == 0) {
                width = Integer.MAX_VALUE;
            }
            Insets in = target.getInsets();
            int max = width - in.left - in.right - 2 * getHgap();
            int rowWidth = 0;
            int rowHeight = 0;
            int w = 0;
            int h = 0;
            for (Component c : target.getComponents()) {
                if (!c.isVisible()) {
                    continue;
                }
                Dimension d = preferred ? c.getPreferredSize() : c.getMinimumSize();
                if (rowWidth > 0 && rowWidth + getHgap() + d.width > max) {
                    w = StrictMath.max(w, rowWidth);
                    h += rowHeight + getVgap();
                    rowWidth = 0;
                    rowHeight = 0;
                }
                rowWidth += (rowWidth > 0 ? getHgap() : 0) + d.width;
                rowHeight = StrictMath.max(rowHeight, d.height);
            }
            w = StrictMath.max(w, rowWidth);
            h += rowHeight;
            return new Dimension(w + in.left + in.right + 2 * getHgap(), h + in.top + in.bottom + 2 * getVgap());
        }
    }
}
