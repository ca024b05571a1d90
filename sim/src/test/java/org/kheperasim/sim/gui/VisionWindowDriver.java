package org.kheperasim.sim.gui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.cli.Main;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * Runs in a child JVM under Xvfb (see {@link VisionWindowTest}): before the run the strip is hidden;
 * once the controller has read its turret the strip shows, below the sensor panel, with the image's
 * brightest pixel drawn brightest.
 *
 * <p>Arguments: output folder, controller classes folder.
 */
public final class VisionWindowDriver {
    private VisionWindowDriver() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        int code = Main.commandLine().execute("gui", "--arena", "lab", "--classpath", args[1], "--controller", "LampSeeker",
                "--seed", "2");
        if (code != 0) {
            fail("the gui command returned " + code);
        }
        MainWindow w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        Robot robot = new Robot();
        robot.waitForIdle();
        VisionStrip strip = onEdt(() -> find(w.frame().getContentPane(), VisionStrip.class));
        SensorPanel panel = onEdt(() -> find(w.frame().getContentPane(), SensorPanel.class));
        if (strip == null || panel == null) {
            fail("the window has no vision strip or sensor panel");
        }
        if (onEdt(strip::isShowing)) {
            fail("the strip shows before any controller read the turret");
        }
        SwingUtilities.invokeAndWait(() -> w.action("start").actionPerformed(null));
        long start = System.nanoTime();
        Snapshot last = null;
        while (System.nanoTime() - start < 60_000_000_000L) {
            last = w.runner() == null ? null : w.runner().latest();
            if (last != null && last.timeSeconds() >= 2 && last.vision(0).isPresent() && onEdt(strip::isShowing)) {
                break;
            }
            Thread.sleep(20);
        }
        if (last == null || last.vision(0).isEmpty() || !onEdt(strip::isShowing)) {
            fail("after 60 s: " + (last == null ? "no snapshot" : "at " + last.timeSeconds() + " s, image "
                    + last.vision(0).isPresent()) + ", strip showing " + onEdt(strip::isShowing));
        }
        SwingUtilities.invokeAndWait(() -> w.action("pause").actionPerformed(null));
        robot.waitForIdle();
        Thread.sleep(300);
        Rectangle s = onEdt(() -> new Rectangle(strip.getLocationOnScreen(), strip.getSize()));
        Rectangle p = onEdt(() -> new Rectangle(panel.getLocationOnScreen(), panel.getSize()));
        if (s.y < p.y + p.height - 2 || StrictMath.abs(s.x - p.x) > 2 || s.height < VisionStrip.PREFERRED_HEIGHT - 2) {
            fail("the strip is not under the sensor panel: strip " + s + ", panel " + p);
        }
        shot(robot, out.resolve("vision-1-strip.png"));
        System.out.println("strip " + s + " under the sensor panel " + p);
        System.out.println("VISION WINDOW OK");
        SwingUtilities.invokeAndWait(() -> w.action("close").actionPerformed(null));
        System.exit(0);
    }

    private static <T extends Component> T find(Container c, Class<T> type) {
        for (Component child : c.getComponents()) {
            if (type.isInstance(child)) {
                return type.cast(child);
            }
            if (child instanceof Container inner) {
                T t = find(inner, type);
                if (t != null) {
                    return t;
                }
            }
        }
        return null;
    }

    private static void shot(Robot robot, Path file) throws Exception {
        Rectangle screen = new Rectangle(Toolkit.getDefaultToolkit().getScreenSize());
        ImageIO.write(robot.createScreenCapture(screen), "png", file.toFile());
    }

    private static <T> T onEdt(java.util.function.Supplier<T> s) throws Exception {
        Object[] box = new Object[1];
        SwingUtilities.invokeAndWait(() -> box[0] = s.get());
        @SuppressWarnings("unchecked")
        T t = (T) box[0];
        return t;
    }

    private static void fail(String why) {
        System.out.println("FAIL: " + why);
        System.exit(1);
    }
}
