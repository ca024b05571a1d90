package org.kheperasim.sim.gui;

import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.onEdt;

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
 * Runs in a child JVM under Xvfb (see {@link WsuCorpusWindowTest}): the window opens a course's
 * world file and its compiled classes, trusts the controller (it opens a window of its own), runs it
 * for 5 simulated seconds with that window open, takes a screenshot and stops.
 *
 * <p>Arguments: output folder, world file, classes folder, controller name, screenshot file name.
 */
public final class WsuCorpusWindowDriver {
    private WsuCorpusWindowDriver() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        int code = Main.commandLine().execute("gui", "--arena", args[1], "--classpath", args[2], "--controller", args[3],
                "--seed", "3");
        if (code != 0) {
            fail("the gui command returned " + code);
        }
        MainWindow w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        Robot robot = new Robot();
        robot.waitForIdle();
        SwingUtilities.invokeAndWait(() -> trust(w.frame().getJMenuBar()));
        SwingUtilities.invokeAndWait(() -> w.action("start").actionPerformed(null));
        long start = System.nanoTime();
        Snapshot last = null;
        while (System.nanoTime() - start < 90_000_000_000L) {
            last = w.runner() == null ? null : w.runner().latest();
            if (last != null && last.timeSeconds() >= 5 && ownWindow(w) != null) {
                break;
            }
            Thread.sleep(20);
        }
        Frame own = ownWindow(w);
        if (own == null || last == null || last.timeSeconds() < 5) {
            fail("after 90 s the run was at " + (last == null ? "no snapshot" : last.timeSeconds() + " s")
                    + " and the controller's window " + (own == null ? "had not opened" : "was open"));
        }
        robot.waitForIdle();
        Thread.sleep(300);
        Rectangle screen = new Rectangle(Toolkit.getDefaultToolkit().getScreenSize());
        ImageIO.write(robot.createScreenCapture(screen), "png", out.resolve(args[4]).toFile());
        String status = onEdt(() -> w.frame().getTitle());
        System.out.printf(Locale.ROOT, "running at %.2f s with the controller's own window open (%s)%n", last.timeSeconds(), status);
        SwingUtilities.invokeAndWait(() -> w.action("stop").actionPerformed(null));
        robot.waitForIdle();
        System.out.println("CORPUS WINDOW OK");
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

    /** @return a frame the controller opened (any showing frame but the simulator's own), or null */
    private static Frame ownWindow(MainWindow w) throws Exception {
        return onEdt(() -> {
            for (Window win : Window.getWindows()) {
                if (win instanceof Frame f && f != w.frame() && f.isDisplayable() && f.isShowing()) {
                    return f;
                }
            }
            return null;
        });
    }


    private static void fail(String why) {
        KeyBindingsDriverSupport.check(false, why);
    }
}
