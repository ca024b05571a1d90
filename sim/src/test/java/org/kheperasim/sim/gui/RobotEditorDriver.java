package org.kheperasim.sim.gui;

import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.onEdt;

import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.geom.Point2D;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import javax.swing.JTable;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.cli.Main;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;
import org.kheperasim.sim.gui.robot.RobotEditor;
import org.kheperasim.sim.gui.robot.RobotFiles;
import org.kheperasim.sim.run.PacedRunner;

/**
 * Runs in a child JVM under Xvfb (see {@link RobotEditorTest}), every robot-editor check in one
 * JVM: Robot > Edit robot on the Khepera I; a sensor turned by dragging its beam's handle and the
 * wheel base typed into the sheet (a bad value refused first); saved, and the file read back; Try
 * in arena (the run restarts with the edited robot); a robot file from scratch opened and run in
 * the arena; a robot designed in the editor from scratch run; a 3-sensor robot drawn, saved, refused
 * by name to Braitenberg and run by a controller written for any robot's sensors.
 * Screenshots under the output folder.
 *
 * <p>Arguments: output folder, the from-scratch robot file, the source of a controller written for any robot.
 */
public final class RobotEditorDriver {
    /** The robot files as the editor reads and writes them. */
    private static final RobotFiles FILES = new RobotFiles();

    private RobotEditorDriver() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        Path scratchFile = Path.of(args[1]);
        Path anyRobot = Path.of(args[2]);
        Path dir = Files.createDirectories(out.resolve("robot-editor"));
        int code = Main.commandLine().execute("gui", "--arena", "lab", "--controller", "Braitenberg", "--seed", "5");
        if (code != 0) {
            fail("the gui command returned " + code);
        }
        MainWindow w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        Robot robot = new Robot();
        robot.setAutoDelay(10);
        settle(robot);
        SwingUtilities.invokeAndWait(() -> w.action("editRobot").actionPerformed(null));
        RobotEditor ed = onEdt(() -> w.robotEditing().last());
        if (ed == null || !onEdt(ed::robot).equals(RobotTypes.KHEPERA1)) {
            fail("Robot > Edit robot should open the editor on khepera1, got " + (ed == null ? "none" : ed.robot().name()));
        }
        settle(robot);
        shot(robot, ed, dir.resolve("editor-1-khepera1.png"));

        // Turn LEFT_90 (heading 90) to 60 degrees by dragging the handle at its beam's tip.
        RobotType.Sensor s0 = RobotTypes.KHEPERA1.sensor(0);
        double range = RobotTypes.KHEPERA1.proximity().response().rangeMm();
        double to = StrictMath.toRadians(60);
        Point from = screen(ed, onEdt(() -> ed.tipOnCanvas(0)));
        Point target = screen(ed, onEdt(() -> ed.onCanvas(s0.xMm() + range * StrictMath.cos(to), s0.yMm() + range * StrictMath.sin(to))));
        drag(robot, from, target);
        double heading = onEdt(() -> ed.robot().sensor(0).headingDeg());
        if (heading != 60) {
            fail("dragging sensor 0's handle from " + from + " to " + target + " should turn it to 60 degrees, it is " + heading);
        }
        // And move FRONT_LEFT's mount 3 mm to the left by dragging the dot.
        RobotType.Sensor s2 = RobotTypes.KHEPERA1.sensor(2);
        drag(robot, screen(ed, onEdt(() -> ed.mountOnCanvas(2))), screen(ed, onEdt(() -> ed.onCanvas(s2.xMm() - 2, s2.yMm() + 3))));
        RobotType.Sensor moved = onEdt(() -> ed.robot().sensor(2));
        if (StrictMath.abs(moved.yMm() - (s2.yMm() + 3)) > 0.51 || StrictMath.abs(moved.xMm() - (s2.xMm() - 2)) > 0.51) {
            fail("dragging sensor 2's mount should put it near (23, 9) mm, it is at (" + moved.xMm() + ", " + moved.yMm() + ")");
        }
        System.out.printf(Locale.ROOT, "drag: sensor 0 heading 90 -> %s; sensor 2 mount (25, 6) -> (%s, %s)%n",
                heading, moved.xMm(), moved.yMm());

        // The sheet: a wheel base wider than the body is refused in one line, then 50 is taken.
        type(robot, ed, "wheel base, mm", "80");
        String refused = onEdt(ed::messageText);
        if (!refused.startsWith("Refused: wheel base 80 mm is wider than the body (55 mm across)")
                || onEdt(() -> ed.robot().drive().wheelBaseMm()) != 53) {
            fail("a wheel base of 80 mm should be refused, the message says '" + refused + "'");
        }
        System.out.println("sheet refused: " + refused);
        shot(robot, ed, dir.resolve("editor-2-refused.png"));
        type(robot, ed, "wheel base, mm", "50");
        if (onEdt(() -> ed.robot().drive().wheelBaseMm()) != 50) {
            fail("typing 50 into the wheel base should set it, it is " + ed.robot().drive().wheelBaseMm()
                    + " ('" + ed.messageText() + "')");
        }
        double[][] rows = onEdt(() -> ed.responseAt(12));
        if (rows.length < 2 || StrictMath.abs(rows[0][1] - 1023 * 0.85) > 1e-9) {
            fail("the response at 12 degrees should start at 1023 x 0.85, rows " + java.util.Arrays.deepToString(rows));
        }
        settle(robot);
        shot(robot, ed, dir.resolve("editor-3-edited.png"));

        // Save, and read the file back.
        Path saved = dir.resolve("khepera1-edited.yaml");
        if (!onEdt(() -> ed.saveTo(saved))) {
            fail("saving failed: " + ed.messageText());
        }
        RobotType back = FILES.load(saved);
        if (!back.equals(onEdt(ed::robot)) || back.drive().wheelBaseMm() != 50 || back.sensor(0).headingDeg() != 60
                || back.sensor(2).yMm() != moved.yMm() || back.sensor(1).headingDeg() != 45) {
            fail("the saved file reads back as something else: " + back);
        }
        System.out.println("saved " + saved + " and read it back: wheel base " + back.drive().wheelBaseMm()
                + " mm, sensor 0 heading " + back.sensor(0).headingDeg());

        // Try in arena: the run restarts with the edited robot.
        SwingUtilities.invokeAndWait(ed::tryIt);
        Snapshot tried = runPast(w, 2);
        RobotType running = tried.robots().get(0).type();
        if (!running.equals(back) || !onEdt(() -> w.model().arena().robotType(0)).equals(back)) {
            fail("after Try in arena the run's robot should be the edited one, it is " + running.name()
                    + " wheel base " + running.drive().wheelBaseMm());
        }
        System.out.println("try in arena: " + onEdt(ed::messageText));
        pause(w, robot);
        GuiE2EDriver.shot(robot, w, dir.resolve("window-1-tried.png"));

        // A robot file made from scratch (not bundled): opened, tried, run.
        RobotEditor fileEd = onEdt(() -> w.robotEditing().openFile(scratchFile));
        if (fileEd == null) {
            fail("the from-scratch robot file did not open");
        }
        settle(robot);
        shot(robot, fileEd, dir.resolve("editor-4-scratch-file.png"));
        SwingUtilities.invokeAndWait(fileEd::tryIt);
        RobotView ran = runPast(w, 20).robots().get(0);
        if (!ran.type().equals(FILES.load(scratchFile)) || ran.distanceMm() < 200) {
            fail("the from-scratch robot should run Braitenberg 200 mm in 20 s: " + ran.type().name() + " went "
                    + ran.distanceMm() + " mm");
        }
        System.out.printf(Locale.ROOT, "from-scratch file %s: %s, radius %s mm, %d sensors, went %.0f mm in 20 s, %d collisions%n",
                scratchFile.getFileName(), ran.type().name(), ran.type().body().radiusMm(), ran.type().sensorCount(),
                ran.distanceMm(), ran.collisions());
        pause(w, robot);
        GuiE2EDriver.shot(robot, w, dir.resolve("window-2-scratch-file.png"));
        SwingUtilities.invokeAndWait(() -> fileEd.frame().dispose());

        // A robot designed in the editor: round, 8 sensors placed by New robot, wheel base 70, run.
        RobotEditor newEd = onEdt(() -> w.robotEditing().newRobot("disc8", 40, 70, 6, 8));
        SwingUtilities.invokeAndWait(newEd::tryIt);
        RobotView disc = runPast(w, 20).robots().get(0);
        if (!disc.type().name().equals("disc8") || disc.type().drive().wheelBaseMm() != 70 || disc.distanceMm() < 150) {
            fail("the robot designed in the editor should run: " + disc.type().name() + " went " + disc.distanceMm() + " mm");
        }
        System.out.printf(Locale.ROOT, "designed in the editor: disc8, radius 40 mm, wheel base 70 mm, went %.0f mm in 20 s%n",
                disc.distanceMm());
        pause(w, robot);
        GuiE2EDriver.shot(robot, w, dir.resolve("window-3-designed.png"));
        SwingUtilities.invokeAndWait(() -> newEd.frame().dispose());

        // A round robot with 3 sensors: drawn, saved, read back.
        RobotEditor tri = onEdt(() -> w.robotEditing().newRobot("tri", 30, 45, 10, 3));
        settle(robot);
        shot(robot, tri, dir.resolve("editor-5-tri.png"));
        Path triFile = dir.resolve("tri.yaml");
        if (!onEdt(() -> tri.saveTo(triFile)) || !FILES.load(triFile).equals(onEdt(tri::robot))
                || FILES.load(triFile).sensorCount() != 3) {
            fail("the 3-sensor robot did not save and read back: " + tri.messageText());
        }
        System.out.println("3-sensor robot saved to " + triFile + " and read back");

        // The 3-sensor robot in the arena: Braitenberg, written for the Khepera's eight, is refused by name;
        // a controller written for any robot's sensors (compiled in the window, as Controller > Open .java) runs it.
        SwingUtilities.invokeAndWait(tri::tryIt);
        long t0 = System.nanoTime();
        while (!w.consoleText().contains("this robot (tri) has 3 sensors") && System.nanoTime() - t0 < 30_000_000_000L) {
            Thread.sleep(50);
        }
        if (!w.consoleText().contains("this robot (tri) has 3 sensors")) {
            fail("Braitenberg on the 3-sensor robot should be refused by name; the console says:\n" + w.consoleText());
        }
        settle(robot);
        SwingUtilities.invokeAndWait(() -> w.frame().toFront());
        settle(robot);
        GuiE2EDriver.shot(robot, w, dir.resolve("window-4-tri-braitenberg-refused.png"));
        if (!onEdt(() -> w.compileAndUse(anyRobot))) {
            fail("AnyRobotAvoider did not compile: " + w.consoleText());
        }
        SwingUtilities.invokeAndWait(w::start);
        RobotView triRan = runPast(w, 20).robots().get(0);
        if (triRan.type().sensorCount() != 3 || triRan.distanceMm() < 150) {
            fail("the 3-sensor robot should run AnyRobotAvoider: " + triRan.type().name() + " went " + triRan.distanceMm() + " mm");
        }
        System.out.printf(Locale.ROOT, "3-sensor robot: Braitenberg refused by name; AnyRobotAvoider went %.0f mm in 20 s%n",
                triRan.distanceMm());
        pause(w, robot);
        GuiE2EDriver.shot(robot, w, dir.resolve("window-5-tri-runs.png"));
        System.out.println("ROBOT EDITOR OK");
        SwingUtilities.invokeAndWait(() -> {
            tri.frame().dispose();
            ed.frame().dispose();
            w.action("stop").actionPerformed(null);
            w.model().markSaved();
            w.action("close").actionPerformed(null);
        });
        System.exit(0);
    }

    /** Types into the sheet's value cell of a property: a double click, select all, the text, Enter. */
    private static void type(Robot robot, RobotEditor ed, String label, String text) throws Exception {
        JTable t = ed.sheet();
        Point p = onEdt(() -> {
            int row = ed.sheetRow(label);
            t.scrollRectToVisible(t.getCellRect(row, 1, true));
            Rectangle r = t.getCellRect(row, 1, true);
            Point o = t.getLocationOnScreen();
            return new Point(o.x + r.x + r.width / 2, o.y + r.y + r.height / 2);
        });
        robot.mouseMove(p.x, p.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        settle(robot);
        robot.keyPress(KeyEvent.VK_CONTROL);
        robot.keyPress(KeyEvent.VK_A);
        robot.keyRelease(KeyEvent.VK_A);
        robot.keyRelease(KeyEvent.VK_CONTROL);
        for (char c : text.toCharArray()) {
            int k = KeyEvent.getExtendedKeyCodeForChar(c);
            robot.keyPress(k);
            robot.keyRelease(k);
        }
        robot.keyPress(KeyEvent.VK_ENTER);
        robot.keyRelease(KeyEvent.VK_ENTER);
        settle(robot);
    }

    private static void drag(Robot robot, Point from, Point to) throws Exception {
        robot.mouseMove(from.x, from.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        for (int i = 1; i <= 10; i++) {
            robot.mouseMove(from.x + (to.x - from.x) * i / 10, from.y + (to.y - from.y) * i / 10);
        }
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        settle(robot);
    }

    private static Point screen(RobotEditor ed, Point2D onCanvas) throws Exception {
        Point o = onEdt(() -> ed.canvas().getLocationOnScreen());
        return new Point(o.x + (int) StrictMath.round(onCanvas.getX()), o.y + (int) StrictMath.round(onCanvas.getY()));
    }

    /**
     * Let the window take what was done: the event queue emptied of what is queued now, a pause for the
     * X server's events (the robot's gestures) to arrive, and the queue emptied again. Not
     * {@code Robot.waitForIdle}: while a run paints, the queue is never idle, and it waited for good.
     */
    private static void settle(Robot robot) throws Exception {
        SwingUtilities.invokeAndWait(() -> { });
        Thread.sleep(250);
        SwingUtilities.invokeAndWait(() -> { });
        Thread.sleep(50);
        SwingUtilities.invokeAndWait(() -> { });
    }

    private static void pause(MainWindow w, Robot robot) throws Exception {
        SwingUtilities.invokeAndWait(() -> {
            w.action("pause").actionPerformed(null);
            w.frame().toFront();
        });
        settle(robot);
        Thread.sleep(300);
    }

    private static Snapshot runPast(MainWindow w, double seconds) throws Exception {
        // As fast as possible while only waiting, the run pausing itself at exactly that moment (the speed never changes
        // what is computed; pauseAt is queued before the speed, so the run cannot pass it); back to x1 before the next
        // gesture, as the window's runs start.
        long target = (long) StrictMath.rint(seconds * 1e9);
        long start = System.nanoTime();
        PacedRunner r = null;
        while (r == null && System.nanoTime() - start < 90_000_000_000L) {
            r = onEdt(() -> {
                PacedRunner live = w.runner();
                if (live != null) {
                    live.pauseAt(target);
                    w.chooseSpeed(PacedRunner.MAX_SPEED);
                }
                return live;
            });
            if (r == null) {
                Thread.sleep(20);
            }
        }
        while (r != null && System.nanoTime() - start < 90_000_000_000L) {
            Snapshot s = r.latest();
            if (r.state() == PacedRunner.State.PAUSED && s != null && s.timeNanos() == target) {
                SwingUtilities.invokeAndWait(() -> w.chooseSpeed(1));
                return s;
            }
            Thread.sleep(20);
        }
        fail("the run did not pause at " + seconds + " s in 90 s: " + w.consoleText());
        return null;
    }

    private static void shot(Robot robot, RobotEditor ed, Path file) throws Exception {
        SwingUtilities.invokeAndWait(() -> ed.frame().toFront());
        settle(robot);
        Rectangle r = onEdt(() -> ed.frame().getBounds());
        Rectangle screen = new Rectangle(Toolkit.getDefaultToolkit().getScreenSize());
        ImageIO.write(robot.createScreenCapture(r.intersection(screen)), "png", file.toFile());
        System.out.println("screenshot " + file);
    }


    private static void fail(String why) {
        KeyBindingsDriverSupport.check(false, why);
    }
}
