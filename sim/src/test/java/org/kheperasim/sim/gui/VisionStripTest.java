package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.engine.view.VisionView;

/** The vision turret's strip: 64 cells in their grey levels, pixel 0 on the left, drawn into an image. */
class VisionStripTest {
    private static BufferedImage draw(VisionView view) {
        BufferedImage img = new BufferedImage(320 + 3, 40, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setColor(java.awt.Color.WHITE);
        g.fillRect(0, 0, img.getWidth(), img.getHeight());
        VisionStrip.draw(g, new Rectangle2D.Double(0, 0, img.getWidth(), img.getHeight()), view);
        g.dispose();
        return img;
    }

    @Test
    void eachPixelIsACellInItsGreyLevelFromLeftToRight() {
        int[] pixels = new int[64];
        for (int i = 0; i < 64; i++) {
            pixels[i] = i * 4;
        }
        pixels[40] = 255;
        BufferedImage img = draw(new VisionView(0, 1_500_000_000L, pixels));
        int y = 32;
        // 320 px for 64 cells: cell i spans x = 1 + 5i .. 5 + 5i.
        for (int i : new int[] {0, 10, 40, 63}) {
            int rgb = img.getRGB(1 + 5 * i + 2, y) & 0xffffff;
            int grey = pixels[i];
            assertEquals((grey << 16) | (grey << 8) | grey, rgb, "cell " + i);
        }
    }

    @Test
    void beforeTheTurretIsReadTheStripIsEmpty() {
        BufferedImage img = draw(null);
        assertEquals(0xffffff, img.getRGB(100, 32) & 0xffffff, "nothing drawn inside the frame");
        assertNotEquals(0xffffff, img.getRGB(1, 32) & 0xffffff, "the frame is drawn");
    }
}
