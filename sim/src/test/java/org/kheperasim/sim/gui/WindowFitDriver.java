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
 * within the screen, with the console on it. Argument: output folder.
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
        SwingUtilities.invokeAndWait(() -> w.action("close").actionPerformed(null));
        System.exit(0);
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
