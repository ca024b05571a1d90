package org.kheperasim.sim.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;

/** Over a run of several robots: each robot's index beside it, and a ring round the one the panels show. */
final class RobotLabels {
    private RobotLabels() {
    }

    /**
     * With several robots, label each with its index and ring the one the panels show.
     *
     * @param selected the selected robot's index
     */
    static void draw(Graphics2D g, ViewTransform view, Snapshot snapshot, int selected) {
        if (snapshot == null || snapshot.robots().size() < 2) {
            return;
        }
        g.setFont(g.getFont().deriveFont(Font.BOLD, 11f));
        for (RobotView r : snapshot.robots()) {
            double radius = view.len(r.type().body().radiusMm());
            if (r.id() == selected) {
                g.setColor(new Color(0x1E6FFF));
                g.setStroke(new BasicStroke(2.5f));
                g.draw(new Ellipse2D.Double(view.sx(r.x()) - radius - 4, view.sy(r.y()) - radius - 4,
                        2 * radius + 8, 2 * radius + 8));
            }
            g.setColor(new Color(0x202830));
            g.drawString(Integer.toString(r.id()), (float) (view.sx(r.x()) + radius + 3),
                    (float) (view.sy(r.y()) - radius));
        }
    }

}
