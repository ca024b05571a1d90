package org.kheperasim.sim.gui;

import java.awt.Frame;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.Window;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.cli.Main;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * Runs in a child JVM under Xvfb (see {@link WsuWindowTest}): the window opens a WSU world file
 * and a WSU controller folder from the command line, runs the controller (which opens its own
 * debug window), and stops; the debug window closes with the run. Screenshots of the whole screen.
 *
 * <p>Arguments: output folder, world file, controller classes folder.
 */
public final class WsuWindowDriver {
    private WsuWindowDriver() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        int code = Main.commandLine().execute("gui", "--arena", args[1], "--classpath", args[2], "--controller",
                "WsuDebugWindow", "--seed", "3");
        if (code != 0) {
            fail("the gui command returned " + code);
        }
        MainWindow w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        Robot robot = new Robot();
        robot.waitForIdle();
        int caps = onEdt(() -> w.model().arena().caps().size());
        int walls = onEdt(() -> w.model().arena().walls().size());
        System.out.println("opened the WSU world: " + walls + " walls, " + caps + " caps");
        if (caps != 1 || walls < 6) {
            fail("the WSU world did not load as written (1 cap, 2 walls + 4 border walls): " + walls + " walls, " + caps + " caps");
        }
        // A controller that opens a window of its own runs only trusted (docs/controller-rules.md): Controller > Trust.
        SwingUtilities.invokeAndWait(() -> trust(w.frame().getJMenuBar()));
        SwingUtilities.invokeAndWait(() -> w.action("start").actionPerformed(null));
        long start = System.nanoTime();
        Snapshot last = null;
        while (System.nanoTime() - start < 60_000_000_000L) {
            last = w.runner() == null ? null : w.runner().latest();
            if (last != null && last.timeSeconds() >= 3 && debugWindow() != null) {
                break;
            }
            Thread.sleep(20);
        }
        Frame debug = debugWindow();
        if (debug == null || last == null || last.timeSeconds() < 3) {
            fail("after 60 s the run was at " + (last == null ? "no snapshot" : last.timeSeconds() + " s")
                    + " and the controller's window " + (debug == null ? "had not opened" : "was open"));
        }
        robot.waitForIdle();
        Thread.sleep(300);
        shot(robot, out.resolve("wsu-1-running-with-debug-window.png"));
        System.out.printf(Locale.ROOT, "running at %.2f s with the controller's window '%s'%n", last.timeSeconds(),
                debug.getTitle());
        SwingUtilities.invokeAndWait(() -> w.action("stop").actionPerformed(null));
        long until = System.nanoTime() + 20_000_000_000L;
        while (debugWindow() != null && System.nanoTime() < until) {
            Thread.sleep(50);
        }
        robot.waitForIdle();
        shot(robot, out.resolve("wsu-2-stopped.png"));
        if (debugWindow() != null) {
            fail("the controller's window was still open 20 s after the run was stopped");
        }
        System.out.println("WSU WINDOW OK");
        SwingUtilities.invokeAndWait(() -> w.action("close").actionPerformed(null));
        System.exit(0);
    }

    /** Tick Controller > Trust this controller, as a user who vouches for the code does. */
    private static void trust(javax.swing.JMenuBar bar) {
        for (int i = 0; i < bar.getMenuCount(); i++) {
            javax.swing.JMenu menu = bar.getMenu(i);
            for (int j = 0; menu != null && j < menu.getItemCount(); j++) {
                if (menu.getItem(j) instanceof javax.swing.JCheckBoxMenuItem item && item.getText().startsWith("Trust this controller")
                        && !item.isSelected()) {
                    item.doClick();
                    return;
                }
            }
        }
        fail("no Trust this controller item in the window's menus");
    }

    /** @return the controller's debug window while it is open */
    private static Frame debugWindow() throws Exception {
        return onEdt(() -> {
            for (Window win : Window.getWindows()) {
                if (win instanceof Frame f && "WSU debug".equals(f.getTitle()) && f.isDisplayable() && f.isShowing()) {
                    return f;
                }
            }
            return null;
        });
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
