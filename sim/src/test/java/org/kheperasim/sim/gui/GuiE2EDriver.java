package org.kheperasim.sim.gui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.event.KeyEvent;
import java.io.File;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.cli.Main;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * Run in a child JVM under Xvfb by {@link GuiEndToEndTest}: opens the real window through the
 * command line's entry point, then, with {@link Robot} like a user, picks the wall tool, drags a
 * wall across the robot's path, chooses Braitenberg, starts, and checks the robot turned away
 * from the wall. Saves screenshots. Exit status 0 when all is well; prints why otherwise.
 */
public final class GuiE2EDriver {
    /** Wall across the lab robot's path: it starts at (609.6, 609.6) facing up (+y). */
    static final double WALL_Y = 760;
    static final double WALL_X1 = 480;
    static final double WALL_X2 = 740;

    private GuiE2EDriver() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args.length > 0 ? args[0] : "target");
        long t0 = System.nanoTime();
        int code = Main.commandLine().execute("gui", "--arena", "lab", "--controller", "WallFollower", "--seed", "3");
        if (code != 0) {
            fail("the gui command returned " + code);
        }
        MainWindow w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        System.out.printf(Locale.ROOT, "window showing after %.2f s%n", (System.nanoTime() - t0) / 1e9);
        Robot robot = new Robot();
        robot.setAutoDelay(15);
        RobotInput input = new RobotInput(robot);
        input.settle();

        click(input, find(w.frame(), "tool.WALL"));
        Point a = screen(w, WALL_X1, WALL_Y);
        Point b = screen(w, WALL_X2, WALL_Y);
        input.move(a);
        input.press();
        for (int i = 1; i <= 20; i++) {
            input.move(new Point(a.x + (b.x - a.x) * i / 20, a.y + (b.y - a.y) * i / 20));
        }
        input.release();
        int walls = onEdt(() -> w.model().arena().walls().size());
        if (walls != 5) {
            fail("dragging with the wall tool should add a fifth wall; the arena has " + walls);
        }
        System.out.println("drew wall " + onEdt(() -> w.model().arena().walls().get(4)));
        shot(robot, w, out.resolve("e2e-1-wall-drawn.png"));

        // Choose Braitenberg in the controller box, with the keyboard as a user may.
        click(input, find(w.frame(), "controller"));
        input.keys(KeyEvent.VK_B);
        input.keys(KeyEvent.VK_ENTER);
        String chosen = onEdt(w::controllerName);
        if (!chosen.equals("Braitenberg")) {
            fail("choosing Braitenberg in the controller box gave " + chosen);
        }
        // x4: the 12 simulated seconds take 3 s of wall time; the speed never changes what is computed.
        SwingUtilities.invokeAndWait(() -> w.chooseSpeed(4));
        click(input, find(w.frame(), "start"));
        long start = System.nanoTime();
        double maxY = 0;
        double minHeadingOff = 0;
        Snapshot last = null;
        boolean shotMid = false;
        while (System.nanoTime() - start < 60_000_000_000L) {
            Snapshot s = w.runner() == null ? null : w.runner().latest();
            if (s != null && !s.robots().isEmpty()) {
                RobotView r = s.robots().get(0);
                maxY = StrictMath.max(maxY, r.y());
                minHeadingOff = StrictMath.max(minHeadingOff, StrictMath.abs(angleOff(r.headingDeg(), 90)));
                last = s;
                if (!shotMid && s.timeSeconds() > 5) {
                    shot(robot, w, out.resolve("e2e-2-running.png"));
                    shotMid = true;
                }
                if (s.timeSeconds() >= 12) {
                    break;
                }
            }
            Thread.sleep(20);
        }
        shot(robot, w, out.resolve("e2e-3-turned-away.png"));
        if (last == null || last.timeSeconds() < 12) {
            fail("the run did not reach 12 s simulated within 60 s: " + (last == null ? "no snapshot" : last.timeSeconds()));
        }
        RobotView r = last.robots().get(0);
        double limit = WALL_Y - 4;
        System.out.printf(Locale.ROOT, "robot at t=%.2f s: (%.1f, %.1f) heading %.1f; closest approach y=%.1f (wall face at %.1f);"
                + " largest turn from the start heading %.1f deg%n", last.timeSeconds(), r.x(), r.y(), r.headingDeg(), maxY, limit, minHeadingOff);
        if (maxY + 27.5 > limit + 1) {
            fail("the robot went through the wall: its body reached y=" + (maxY + 27.5));
        }
        if (maxY < WALL_Y - 150) {
            fail("the robot never came near the wall (max y " + maxY + "): the wall did not test anything");
        }
        if (minHeadingOff < 60 || r.y() > maxY - 20 && StrictMath.abs(angleOff(r.headingDeg(), 90)) < 60) {
            fail("the robot did not turn away from the wall");
        }
        System.out.println("E2E OK");
        // The drawn wall is not to be kept: no save prompt.
        SwingUtilities.invokeAndWait(() -> w.model().markSaved());
        SwingUtilities.invokeAndWait(() -> w.action("close").actionPerformed(null));
        System.exit(0);
    }

    private static double angleOff(double a, double b) {
        double d = (a - b) % 360;
        if (d > 180) {
            d -= 360;
        } else if (d < -180) {
            d += 360;
        }
        return d;
    }

    private static void fail(String why) {
        System.out.println("E2E FAILED: " + why);
        System.exit(1);
    }

    private static <T> T onEdt(java.util.function.Supplier<T> s) throws Exception {
        AtomicReference<T> ref = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> ref.set(s.get()));
        return ref.get();
    }

    private static Point screen(MainWindow w, double x, double y) throws Exception {
        return onEdt(() -> {
            Point o = w.arenaComponent().getLocationOnScreen();
            return new Point(o.x + (int) StrictMath.round(w.view().sx(x)), o.y + (int) StrictMath.round(w.view().sy(y)));
        });
    }

    private static Component find(Container root, String name) throws Exception {
        Component c = onEdt(() -> search(root, name));
        if (c == null) {
            fail("no component named " + name);
        }
        return c;
    }

    private static Component search(Container root, String name) {
        for (Component c : root.getComponents()) {
            if (name.equals(c.getName())) {
                return c;
            }
            if (c instanceof Container k) {
                Component f = search(k, name);
                if (f != null) {
                    return f;
                }
            }
        }
        return null;
    }

    private static void click(RobotInput input, Component c) throws Exception {
        input.click(onEdt(() -> {
            Point o = c.getLocationOnScreen();
            return new Point(o.x + c.getWidth() / 2, o.y + c.getHeight() / 2);
        }));
    }

    static void shot(Robot robot, MainWindow w, Path file) throws Exception {
        Rectangle r = onEdt(() -> w.frame().getBounds());
        Rectangle screen = new Rectangle(Toolkit.getDefaultToolkit().getScreenSize());
        File f = file.toFile();
        f.getParentFile().mkdirs();
        ImageIO.write(robot.createScreenCapture(r.intersection(screen)), "png", f);
        System.out.println("screenshot " + file);
    }
}
