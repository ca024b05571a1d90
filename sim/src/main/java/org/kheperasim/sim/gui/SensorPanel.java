package org.kheperasim.sim.gui;

import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.Graphics;
import java.util.function.Supplier;
import javax.swing.JComponent;
import org.kheperasim.sim.engine.view.RobotView;

/** Hosts {@link SensorRenderer#draw} for the selected robot of the latest snapshot. */
final class SensorPanel extends JComponent {
    private final Supplier<RobotView> robot;
    private final Supplier<String> runState;

    /**
     * @param robot the robot to show (the selected one of the latest snapshot)
     * @param runState the run's state in words, or null
     */
    SensorPanel(Supplier<RobotView> robot, Supplier<String> runState) {
        this.robot = robot;
        this.runState = runState;
        setName("sensorPanel");
        setPreferredSize(new Dimension(SensorRenderer.BASE_WIDTH, SensorRenderer.BASE_HEIGHT));
    }

    @Override
    protected void paintComponent(Graphics g) {
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            SensorRenderer.draw(g2, getWidth(), getHeight(), robot.get(), runState.get());
        } finally {
            g2.dispose();
        }
    }
}
