package org.kheperasim.sim.gui;

import java.awt.BasicStroke;
import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.GridLayout;
import java.awt.Insets;
import java.awt.RenderingHints;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import javax.swing.JComponent;
import javax.swing.JPanel;
import javax.swing.JToggleButton;
import org.kheperasim.sim.engine.RobotView;
import org.kheperasim.sim.engine.Snapshot;

/**
 * A rolling plot of chosen sensors over the last {@link #WINDOW_S} simulated seconds. Fed from the
 * window's timer with the latest snapshot (on the event thread); at high speeds it shows what the
 * screen sampled, which is all a person can see anyway.
 */
final class PlotPanel extends JPanel {
    static final double WINDOW_S = 10;
    private static final int SERIES = 16;
    private static final int CAPACITY = 4096;
    private static final Color[] COLOURS = {
        new Color(0xE6194B), new Color(0x3CB44B), new Color(0x4363D8), new Color(0xF58231),
        new Color(0x911EB4), new Color(0x42D4F4), new Color(0xF032E6), new Color(0x9A6324),
    };

    private final double[] times = new double[CAPACITY];
    private final int[][] values = new int[SERIES][CAPACITY];
    private int start;
    private int count;
    private double lastTime = -1;
    private final JToggleButton[] chosen = new JToggleButton[SERIES];
    private final JComponent canvas;

    PlotPanel() {
        super(new BorderLayout());
        setName("plotPanel");
        JPanel buttons = new JPanel(new GridLayout(2, 8, 1, 1));
        for (int i = 0; i < SERIES; i++) {
            JToggleButton b = new JToggleButton((i < 8 ? "P" : "L") + (i % 8), i == 2 || i == 3);
            b.setMargin(new Insets(0, 1, 0, 1));
            b.setFont(b.getFont().deriveFont(10f));
            b.setForeground(COLOURS[i % 8]);
            b.setToolTipText(i < 8 ? "plot proximity sensor " + i : "plot light sensor " + (i - 8));
            b.addActionListener(e -> repaint());
            chosen[i] = b;
            buttons.add(b);
        }
        canvas = new JComponent() {
            @Override
            protected void paintComponent(Graphics g) {
                paintPlot((Graphics2D) g, getWidth(), getHeight());
            }
        };
        canvas.setPreferredSize(new Dimension(320, 140));
        add(buttons, BorderLayout.NORTH);
        add(canvas, BorderLayout.CENTER);
    }

    /**
     * @param s the latest snapshot; added if simulated time moved on
     * @param robot the robot whose sensors are plotted
     */
    void sample(Snapshot s, int robot) {
        if (s == null || s.robots().isEmpty()) {
            return;
        }
        double t = s.timeSeconds();
        if (t < lastTime) {
            clear();
        }
        if (t == lastTime) {
            return;
        }
        lastTime = t;
        RobotView r = s.robots().get(robot >= 0 && robot < s.robots().size() ? robot : 0);
        int at = (start + count) % CAPACITY;
        times[at] = t;
        for (int i = 0; i < 8; i++) {
            values[i][at] = r.proximity(i);
            values[8 + i][at] = r.light(i);
        }
        if (count < CAPACITY) {
            count++;
        } else {
            start = (start + 1) % CAPACITY;
        }
        canvas.repaint();
    }

    void clear() {
        start = 0;
        count = 0;
        lastTime = -1;
        canvas.repaint();
    }

    private void paintPlot(Graphics2D g, int w, int h) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fill(new Rectangle2D.Double(0, 0, w, h));
        g.setColor(new Color(0xDDDDDD));
        for (int v = 0; v <= 1024; v += 256) {
            double y = h - 4 - (h - 8) * v / 1024.0;
            g.draw(new Rectangle2D.Double(0, y, w, 0));
        }
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 9));
        g.setColor(Color.GRAY);
        g.drawString("1023", 2, 12);
        g.drawString("last " + (int) WINDOW_S + " s", w - 50, h - 6);
        if (count < 2) {
            return;
        }
        double tEnd = times[(start + count - 1) % CAPACITY];
        double tStart = tEnd - WINDOW_S;
        g.setStroke(new BasicStroke(1.3f));
        for (int sIdx = 0; sIdx < SERIES; sIdx++) {
            if (!chosen[sIdx].isSelected()) {
                continue;
            }
            g.setColor(COLOURS[sIdx % 8]);
            if (sIdx >= 8) {
                g.setStroke(new BasicStroke(1.3f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f, new float[] {4f, 2f}, 0f));
            } else {
                g.setStroke(new BasicStroke(1.3f));
            }
            Path2D.Double p = new Path2D.Double();
            boolean first = true;
            for (int k = 0; k < count; k++) {
                int at = (start + k) % CAPACITY;
                if (times[at] < tStart) {
                    continue;
                }
                double x = (times[at] - tStart) / WINDOW_S * w;
                double y = h - 4 - (h - 8) * StrictMath.min(1023, StrictMath.max(0, values[sIdx][at])) / 1024.0;
                if (first) {
                    p.moveTo(x, y);
                    first = false;
                } else {
                    p.lineTo(x, y);
                }
            }
            g.draw(p);
        }
    }
}
