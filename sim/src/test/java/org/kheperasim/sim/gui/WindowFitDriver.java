package org.kheperasim.sim.gui;

import java.awt.Rectangle;
import java.awt.Robot;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.cli.Main;

/**
 * Runs in a child JVM under a 1366 × 768 Xvfb screen (see {@link WindowFitTest}): the window opens
 * within the screen, with the console on it; at 900 × 600, with a long controller name chosen, the
 * plot and the controller box are still there and the sensor panel readable; at 2400 × 1350 the
 * sensor panel's drawing has grown. Argument: output folder.
 */
public final class WindowFitDriver {
    private WindowFitDriver() {
    }

    public static void main(String[] args) throws Exception {
        int code = Main.commandLine().execute("gui", "--arena", "maze", "--controller", "WallFollower", "--seed", "1");
        if (code != 0) {
            fail("the gui command returned " + code);
        }
        MainWindow w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        Robot robot = new Robot();
        robot.waitForIdle();
        Thread.sleep(500);
        Rectangle screen = onEdt(() -> w.frame().getGraphicsConfiguration().getBounds());
        Rectangle frame = onEdt(() -> w.frame().getBounds());
        Rectangle console = onEdt(() -> {
            java.awt.Component c = KeyBindingsDriverSupport.find(w.frame(), "console");
            java.awt.Point o = c.getLocationOnScreen();
            return new Rectangle(o.x, o.y, c.getWidth(), c.getHeight());
        });
        System.out.println("screen " + screen + ", window " + frame + ", console " + console);
        GuiE2EDriver.shot(robot, w, Path.of(args[0]).resolve("window-fit-1366x768.png"));
        if (!screen.contains(frame)) {
            fail("the window reaches off the screen");
        }
        if (console.height < 120 || !screen.contains(console)) {
            fail("the console is not (wholly) on the screen, at least 120 px tall");
        }
        System.out.println("FIT OK");

        // A long class name in a package: the controller box keeps its width, on the toolbar.
        Path src = java.nio.file.Files.createDirectories(Path.of(args[0]).resolve("fit-src"))
                .resolve("AVeryLongControllerNameForTheMazeAssignment.java");
        java.nio.file.Files.writeString(src, "package edu.wsu.course2026.section3.lab4;\nimport org.kheperasim.api.*;\n"
                + "public class AVeryLongControllerNameForTheMazeAssignment extends Controller {\n"
                + "    @Override protected void doWork() { sleepMillis(100); }\n}\n");
        if (!onEdt(() -> w.compileAndUse(src))) {
            fail("the long-named controller does not compile:\n" + onEdt(w::consoleText));
        }

        // A small window, 900 x 600: the plot and the controller box are there, the sensor panel readable.
        SwingUtilities.invokeAndWait(() -> w.frame().setBounds(0, 0, 900, 600));
        settle(robot);
        Path out = Path.of(args[0]);
        GuiE2EDriver.shot(robot, w, out.resolve("window-fit-900x600.png"));
        String small = parts(w);
        System.out.println("900 x 600: " + small);
        checkParts(w, 0.7);
        System.out.println("SMALL WINDOW OK");

        // A large window: the sensor panel's drawing, text included, grows with it.
        SwingUtilities.invokeAndWait(() -> w.frame().setBounds(0, 0, 2400, 1350));
        settle(robot);
        paint(w, out.resolve("window-fit-2400x1350.png"));
        System.out.println("2400 x 1350: " + parts(w));
        checkParts(w, 1.6);
        System.out.println("LARGE WINDOW OK");
        System.exit(0);
    }

    private static void settle(Robot robot) throws Exception {
        robot.waitForIdle();
        Thread.sleep(700);
        SwingUtilities.invokeAndWait(() -> { });
        robot.waitForIdle();
    }

    /** The window's content painted into a picture (a window larger than the screen cannot be captured from it). */
    private static void paint(MainWindow w, Path file) throws Exception {
        java.awt.image.BufferedImage img = onEdt(() -> {
            java.awt.Container c = w.frame().getContentPane();
            java.awt.image.BufferedImage i = new java.awt.image.BufferedImage(c.getWidth(), c.getHeight(),
                    java.awt.image.BufferedImage.TYPE_INT_RGB);
            java.awt.Graphics2D g = i.createGraphics();
            c.paint(g);
            g.dispose();
            return i;
        });
        javax.imageio.ImageIO.write(img, "png", file.toFile());
        System.out.println("picture " + file);
    }

    private static String parts(MainWindow w) throws Exception {
        return onEdt(() -> {
            java.awt.Component plot = KeyBindingsDriverSupport.find(w.frame(), "plotPanel");
            java.awt.Component sensors = KeyBindingsDriverSupport.find(w.frame(), "sensorPanel");
            java.awt.Component box = KeyBindingsDriverSupport.find(w.frame(), "controller");
            return "plot " + plot.getWidth() + "x" + plot.getHeight() + (plot.isShowing() ? "" : " hidden") + ", sensor panel "
                    + sensors.getWidth() + "x" + sensors.getHeight() + " at scale "
                    + String.format(java.util.Locale.ROOT, "%.2f", SensorRenderer.scale(sensors.getWidth(), sensors.getHeight()))
                    + ", controller box at x " + javax.swing.SwingUtilities.convertPoint(box.getParent(), box.getLocation(),
                            w.frame().getContentPane()).x + ".." + (javax.swing.SwingUtilities.convertPoint(box.getParent(),
                            box.getLocation(), w.frame().getContentPane()).x + box.getWidth()) + " of "
                    + w.frame().getContentPane().getWidth() + (box.isShowing() ? "" : " hidden");
        });
    }

    private static void checkParts(MainWindow w, double minScale) throws Exception {
        String problem = onEdt(() -> {
            java.awt.Container content = w.frame().getContentPane();
            java.awt.Component plot = KeyBindingsDriverSupport.find(w.frame(), "plotPanel");
            java.awt.Component sensors = KeyBindingsDriverSupport.find(w.frame(), "sensorPanel");
            java.awt.Component box = KeyBindingsDriverSupport.find(w.frame(), "controller");
            Rectangle b = javax.swing.SwingUtilities.convertRectangle(box.getParent(), box.getBounds(), content);
            if (!plot.isShowing() || plot.getHeight() < 150 || plot.getWidth() < 250) {
                return "the plot is hidden or too small: " + plot.getWidth() + "x" + plot.getHeight();
            }
            if (!box.isShowing() || b.x < 0 || b.x + b.width > content.getWidth() || b.y + b.height > content.getHeight()) {
                return "the controller box is not on the window: " + b + " in " + content.getSize();
            }
            double s = SensorRenderer.scale(sensors.getWidth(), sensors.getHeight());
            return s < minScale ? "the sensor panel is drawn at scale " + s + ", less than " + minScale : null;
        });
        if (problem != null) {
            fail(problem);
        }
    }

    private static <T> T onEdt(java.util.function.Supplier<T> s) throws Exception {
        AtomicReference<T> ref = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> ref.set(s.get()));
        return ref.get();
    }

    private static void fail(String why) {
        System.out.println("FAIL: " + why);
        System.exit(1);
    }
}
