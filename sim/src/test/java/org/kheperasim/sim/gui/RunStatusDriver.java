package org.kheperasim.sim.gui;

import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.check;
import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.onEdt;
import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.onEdtQuiet;
import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.waitFor;

import java.awt.Component;
import java.awt.Robot;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JList;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.cli.Main;
import org.kheperasim.sim.edit.ArenaEdits;
import org.kheperasim.sim.run.PacedRunner;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;
import org.kheperasim.sim.task.RunFacts;
import org.kheperasim.sim.task.Score;

/**
 * Runs in a child JVM under Xvfb (see {@link RunStatusTest}): what the window tells about a run.
 * The score in {@code lab} (a cover task) is {@code run}'s at a paused moment and at the end, and
 * the run ends at the arena's time limit as {@code run} does; the status bar follows the run and
 * turns red, naming the line, when the controller throws; a refused placement's reason is in the
 * console; the palette's letters work with the focus in the console; Help lists titles and closes
 * with Esc; Open .java offers .java files. Arguments: output folder.
 */
public final class RunStatusDriver {
    private static final long SEED = 7;
    private static Robot robot;
    private static RobotInput input;
    private static MainWindow w;

    private RunStatusDriver() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        int code = Main.commandLine().execute("gui", "--arena", "lab", "--controller", "Braitenberg", "--seed", Long.toString(SEED));
        check(code == 0, "the gui command returned " + code);
        w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        robot = new Robot();
        robot.setAutoDelay(20);
        input = new RobotInput(robot);
        robot.waitForIdle();
        Arena lab = ArenaFormat.loadBundled("lab");

        // The score at a paused moment: run's for a run of that length. (The window showed 0/100 all run long.)
        long pauseNanos = 100_000_000_000L;
        SwingUtilities.invokeAndWait(() -> {
            w.chooseSpeed(PacedRunner.MAX_SPEED);
            w.action("start").actionPerformed(null);
            w.runner().pauseAt(pauseNanos);
        });
        waitFor("the run pauses at 100 s", () -> w.runner().state() == PacedRunner.State.PAUSED
                && w.runner().latest().timeNanos() == pauseNanos);
        Thread.sleep(300);
        String atPause = headless(lab, 100).summary();
        check(atPause.equals(onEdt(() -> w.score().summary())), "at 100 s the window scores " + onEdt(() -> w.score().summary())
                + ", run scores " + atPause);
        check(atPause.startsWith(onEdt(() -> w.status().scoreShown()).replaceFirst("^score ", "")),
                "the status bar shows run's score " + atPause + ": '" + onEdt(() -> w.status().scoreShown()) + "'");
        check(!atPause.startsWith("0/"), "Braitenberg has covered some floor by 100 s: " + atPause);
        String paused = onEdt(() -> w.status().message());
        check(paused.startsWith("Paused at t = 100.000 s"), "the status bar says the run is paused: " + paused);
        System.out.println("SCORE AT PAUSE OK: " + atPause);

        // The end: at the arena's time limit, as run ends, with run's score.
        SwingUtilities.invokeAndWait(() -> {
            w.runner().pauseAt(Long.MAX_VALUE);
            w.action("start").actionPerformed(null);
        });
        waitFor("the run ends at the arena's time limit", () -> w.runner().state() == PacedRunner.State.TIME_UP);
        Thread.sleep(300);
        long end = w.runner().latest().timeNanos();
        check(end == 600_000_000_000L, "the run ends at 600 s, the arena's time limit, not at " + end / 1e9 + " s");
        String atEnd = headless(lab, lab.assignment().timeLimitSeconds()).summary();
        check(atEnd.equals(onEdt(() -> w.score().summary())), "at the end the window scores "
                + onEdt(() -> w.score().summary()) + ", run scores " + atEnd);
        String console = onEdt(w::consoleText);
        check(console.contains("Time is up: the arena lab gives a run 600 s, and the run ended at t = 600.000 s, score " + atEnd),
                "the console says the time is up, with the score:\n" + console);
        check(onEdt(() -> w.status().message()).startsWith("Time is up"), "the status bar says so: " + onEdt(() -> w.status().message()));
        check(onEdt(() -> w.action("start").isEnabled() && !w.action("step").isEnabled()), "Start runs again; Step has nothing to step");
        GuiE2EDriver.shot(robot, w, out.resolve("status-1-time-up.png"));
        System.out.println("TIME LIMIT OK: " + atEnd);

        // A controller that throws: the status bar goes from "loaded" to running to red, naming the line.
        Path src = Files.createDirectories(out.resolve("status-src")).resolve("Thrower.java");
        Files.writeString(src, "import org.kheperasim.api.*;\n\npublic class Thrower extends Controller {\n"
                + "    private final int[] readings = new int[10];\n    private int n;\n\n    @Override\n"
                + "    protected void doWork() {\n        readings[n++] = proximity(IrSensor.FRONT_LEFT);\n"
                + "        setSpeeds(3, 3);\n        sleepMillis(100);\n    }\n}\n");
        check(onEdt(() -> w.compileAndUse(src)), "Thrower compiles:\n" + onEdt(w::consoleText));
        check(onEdt(() -> w.status().message()).contains("Thrower loaded"), "loaded: " + onEdt(() -> w.status().message()));
        SwingUtilities.invokeAndWait(() -> {
            w.chooseSpeed(1);
            w.action("start").actionPerformed(null);
        });
        waitFor("the status bar says Thrower runs", () -> onEdtQuiet(() -> w.status().message()).startsWith("Running Thrower in lab"));
        waitFor("the status bar turns red when Thrower throws", () -> onEdtQuiet(() -> w.status().messageRed()));
        waitFor("the red status names the student's line", () -> onEdtQuiet(() -> w.status().message()).contains("Thrower.java:9"));
        Thread.sleep(500);
        String red = onEdt(() -> w.status().message());
        check(red.contains("Thrower threw java.lang.ArrayIndexOutOfBoundsException") && red.contains("Thrower.java:9"),
                "the red status names the exception and the student's line: " + red);
        check(onEdt(() -> w.status().messageRed()), "and stays red once the run has ended: " + red);
        GuiE2EDriver.shot(robot, w, out.resolve("status-2-thrown.png"));
        System.out.println("EXCEPTION STATUS OK: " + red);

        // A refused placement: its whole reason in the console as well as in the status bar.
        SwingUtilities.invokeAndWait(() -> w.action("reset").actionPerformed(null));
        boolean applied = onEdt(() -> w.model().apply(ArenaEdits.setRobot(w.model().arena(), 0,
                new org.kheperasim.sim.arena.Pose(20, 600, 0))));
        check(!applied, "a robot start across the left wall is refused");
        String reason = onEdt(() -> w.model().lastRefusal());
        Thread.sleep(200);
        check(onEdt(w::consoleText).contains("refused: " + reason), "the console has the whole reason: " + reason);
        System.out.println("REFUSAL OK: " + reason);

        // The palette's letters with the focus in the console.
        KeyBindingsDriverSupport.clickCorner(input, onEdt(() -> KeyBindingsDriverSupport.find(w.frame(), "consoleText")));
        waitFor("the click puts the focus in the console", () -> onEdtQuiet(() -> {
            Component f = java.awt.KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner();
            return f != null && "consoleText".equals(f.getName());
        }));
        press(KeyEvent.VK_W, "W chooses the wall tool", () -> onEdtQuiet(() -> w.status().message()).startsWith("Wall:"));
        press(KeyEvent.VK_C, "C chooses the cap tool", () -> onEdtQuiet(() -> w.status().message()).startsWith("Cap:"));
        press(KeyEvent.VK_S, "S chooses select", () -> onEdtQuiet(() -> w.status().message()).startsWith("Select:"));
        System.out.println("PALETTE KEYS OK");

        // Help: the pages by title; Esc closes it.
        press(KeyEvent.VK_F1, "F1 opens the manual", () -> helpDialog() != null);
        JDialog help = helpDialog();
        String first = onEdt(() -> {
            JList<?> pages = (JList<?>) KeyBindingsDriverSupport.find(help, "help.pages");
            return pages.getModel().getElementAt(0) + " | " + pages.getModel().getElementAt(1);
        });
        check(first.equals("Getting started: a first controller in 15 minutes | The window"), "the pages by title: " + first);
        GuiE2EDriver.shot(robot, w, out.resolve("status-3-help.png"));
        input.settle();
        press(KeyEvent.VK_ESCAPE, "Esc closes the manual", () -> helpDialog() == null);
        System.out.println("HELP OK: " + first);

        // Open .java offers .java files.
        SwingUtilities.invokeLater(() -> w.action("openJava").actionPerformed(null));
        waitFor("Open .java shows a file chooser", () -> chooser() != null);
        JFileChooser c = chooser();
        boolean filters = onEdt(() -> c.getFileFilter().accept(new File("MyFirst.java")) && !c.getFileFilter().accept(new File("notes.txt")));
        GuiE2EDriver.shot(robot, w, out.resolve("status-4-open-java.png"));
        SwingUtilities.invokeAndWait(c::cancelSelection);
        check(filters, "Open .java shows .java files, not every file");
        System.out.println("OPEN JAVA FILTER OK");
        System.exit(0);
    }

    /** The score run prints for the same arena, controller and seed, run for {@code seconds}. */
    private static Score headless(Arena arena, double seconds) {
        RunResult r = Simulation.builder().arena(arena).controller("Braitenberg").seed(SEED).seconds(seconds).run();
        return Score.of(arena, RunFacts.of(r));
    }

    private static JDialog helpDialog() {
        return onEdtQuiet(() -> {
            for (Window win : Window.getWindows()) {
                if (win instanceof JDialog d && d.isShowing() && "help".equals(d.getName())) {
                    return d;
                }
            }
            return null;
        });
    }

    private static JFileChooser chooser() {
        return onEdtQuiet(() -> {
            for (Window win : Window.getWindows()) {
                if (win instanceof JDialog d && d.isShowing()) {
                    Component f = find(d);
                    if (f != null) {
                        return (JFileChooser) f;
                    }
                }
            }
            return null;
        });
    }

    private static Component find(java.awt.Container root) {
        for (Component c : root.getComponents()) {
            if (c instanceof JFileChooser) {
                return c;
            }
            if (c instanceof java.awt.Container k) {
                Component f = find(k);
                if (f != null) {
                    return f;
                }
            }
        }
        return null;
    }

    /**
     * Press a key and wait until it took effect. Not through {@code robot.waitForIdle()}, which waited
     * seconds for a quiet moment in an event queue the window's frame timer keeps busy, nor through
     * {@link RobotInput#keys}: the palette's letters are taken before any component sees them.
     */
    private static void press(int key, String what, BooleanSupplier done) throws Exception {
        robot.keyPress(key);
        robot.keyRelease(key);
        waitFor(what, done);
        System.out.println(what + ": ok");
    }

}
