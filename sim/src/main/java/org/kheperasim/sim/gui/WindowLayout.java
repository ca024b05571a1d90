package org.kheperasim.sim.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.function.DoubleSupplier;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.JSplitPane;

/**
 * Where the window's parts go: toolbar on top (wrapping onto a second row on a narrow window); the
 * arena (with the replay bar under it) left of the sensor panel and the plot; the console below,
 * opened 150 px tall (less on a short window, never under 110 px); the status bar at the bottom.
 * The arena gets about the room its shape needs at the height there is, and the right-hand column
 * the rest, so the sensor panel and the plot grow with the window (see {@link SidePanelLayout}),
 * until the user drags the divider.
 */
final class WindowLayout {
    private static final int CONSOLE_PX = 150;
    private static final int CONSOLE_MIN_PX = 110;
    /** The arena's share of the width, at least and at most. */
    private static final double ARENA_MIN_SHARE = 0.4;
    private static final double ARENA_MAX_SHARE = 0.7;

    private WindowLayout() {
    }

    /**
     * @param arenaAspect the arena's width over its height
     * @return the content pane
     */
    static JComponent content(JFrame frame, JComponent toolbar, JComponent arena, JComponent replayBar,
            JComponent sensors,
            JComponent plot, JComponent console, JComponent statusBar, DoubleSupplier arenaAspect) {
        JPanel right = new JPanel();
        right.setLayout(new SidePanelLayout(sensors, plot));
        right.add(sensors);
        right.add(plot);
        JPanel arenaSide = new JPanel(new BorderLayout());
        arenaSide.add(arena, BorderLayout.CENTER);
        arenaSide.add(replayBar, BorderLayout.SOUTH);
        arenaSide.setMinimumSize(new Dimension(200, 150));
        JSplitPane top = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, arenaSide, right);
        top.setResizeWeight(0.5);
        console.setPreferredSize(new Dimension(900, CONSOLE_PX));
        console.setMinimumSize(new Dimension(200, 60));
        JSplitPane main = new JSplitPane(JSplitPane.VERTICAL_SPLIT, top, console);
        main.setResizeWeight(1);
        boolean[] dragged = {false};
        if (top.getUI() instanceof javax.swing.plaf.basic.BasicSplitPaneUI ui) {
            ui.getDivider().addMouseListener(new java.awt.event.MouseAdapter() {
                @Override
                public void mousePressed(java.awt.event.MouseEvent e) {
                    dragged[0] = true;
                }
            });
        }
        Runnable place = () -> {
            if (dragged[0] || top.getWidth() <= 0) {
                return;
            }
            int w = top.getWidth() - top.getDividerSize();
            int arenaWidth = (int) (top.getHeight() * arenaAspect.getAsDouble()) + 16;
            arenaWidth = (int) StrictMath.max(ARENA_MIN_SHARE * w, StrictMath.min(ARENA_MAX_SHARE * w, arenaWidth));
            top.setDividerLocation(arenaWidth);
        };
        top.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                place.run();
            }
        });
        // However small the screen, the console (compile errors, stack traces) opens at least 110 px tall.
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowOpened(WindowEvent e) {
                int consolePx = StrictMath.max(CONSOLE_MIN_PX, StrictMath.min(CONSOLE_PX, frame.getHeight() / 5));
                main.setDividerLocation(StrictMath.max(150, main.getHeight() - main.getDividerSize() - consolePx));
                main.validate();
                place.run();
            }
        });
        JPanel content = new JPanel(new BorderLayout());
        content.add(toolbar, BorderLayout.NORTH);
        content.add(main, BorderLayout.CENTER);
        content.add(statusBar, BorderLayout.SOUTH);
        // The toolbar's rows depend on its width: lay it out again when the window's width changes.
        content.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                toolbar.revalidate();
            }
        });
        return content;
    }
}
