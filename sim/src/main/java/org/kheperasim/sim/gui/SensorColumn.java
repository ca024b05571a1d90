package org.kheperasim.sim.gui;

import java.awt.BorderLayout;
import java.awt.Graphics;
import java.util.function.Supplier;
import javax.swing.JPanel;
import org.kheperasim.sim.engine.view.VisionView;

/**
 * The selected robot's sensors: the {@link SensorPanel}, and under it the image its K213 vision
 * turret last gave its controller ({@link VisionStrip}), shown once the controller has read the
 * turret. Repainting the column repaints both.
 */
final class SensorColumn extends JPanel {
    private final VisionStrip strip;
    private final Supplier<VisionView> image;

    /**
     * @param sensors the sensor panel
     * @param image the selected robot's last vision image, or null when its turret has not been read
     */
    SensorColumn(SensorPanel sensors, Supplier<VisionView> image) {
        super(new BorderLayout());
        this.image = image;
        this.strip = new VisionStrip(image);
        setName("sensorColumn");
        setOpaque(false);
        add(sensors, BorderLayout.CENTER);
        add(strip, BorderLayout.SOUTH);
        strip.setVisible(false);
    }

    @Override
    public void paint(Graphics g) {
        // The strip takes room only for a robot whose controller reads its turret.
        boolean wanted = image.get() != null;
        if (strip.isVisible() != wanted) {
            strip.setVisible(wanted);
            revalidate();
        }
        super.paint(g);
    }

    /** @return the vision strip (for tests) */
    VisionStrip strip() {
        return strip;
    }
}
