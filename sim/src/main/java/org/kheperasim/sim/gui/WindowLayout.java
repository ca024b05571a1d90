package org.kheperasim.sim.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.JSplitPane;

/**
 * Where the window's parts go: toolbar on top; the arena (with the replay bar under it) left of
 * the sensor panel and the plot; the console below, opened 150 px tall on any screen; the status
 * bar at the bottom.
 */
final class WindowLayout {
    private static final int CONSOLE_PX = 150;

    private WindowLayout() {
    }

    static JComponent content(JFrame frame, JComponent toolbar, JComponent arena, JComponent replayBar, JComponent sensors,
            JComponent plot, JComponent console, JComponent statusBar) {
        JPanel right = new JPanel(new BorderLayout());
        right.add(sensors, BorderLayout.NORTH);
        right.add(plot, BorderLayout.CENTER);
        JPanel arenaSide = new JPanel(new BorderLayout());
        arenaSide.add(arena, BorderLayout.CENTER);
        arenaSide.add(replayBar, BorderLayout.SOUTH);
        JSplitPane top = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, arenaSide, right);
        top.setResizeWeight(1);
        console.setPreferredSize(new Dimension(900, CONSOLE_PX));
        JSplitPane main = new JSplitPane(JSplitPane.VERTICAL_SPLIT, top, console);
        main.setResizeWeight(1);
        // However small the screen, the console (compile errors, stack traces) opens 150 px tall.
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowOpened(WindowEvent e) {
                main.setDividerLocation(StrictMath.max(200, main.getHeight() - main.getDividerSize() - CONSOLE_PX));
            }
        });
        JPanel content = new JPanel(new BorderLayout());
        content.add(toolbar, BorderLayout.NORTH);
        content.add(main, BorderLayout.CENTER);
        content.add(statusBar, BorderLayout.SOUTH);
        return content;
    }
}
