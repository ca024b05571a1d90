package org.kheperasim.sim.gui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Point;
import java.awt.Robot;
import java.awt.event.KeyEvent;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.cli.Main;
import org.kheperasim.sim.run.PacedRunner;

/**
 * Runs in a child JVM under Xvfb (see {@link KeyBindingsTest}): presses F5, F6, F7, F8, F10 and
 * Space with the focus in the arena view and then in the console, and checks what each did.
 */
public final class KeyBindingsDriver {
    private static Robot robot;
    private static RobotInput input;
    private static MainWindow w;

    private KeyBindingsDriver() {
    }

    public static void main(String[] args) throws Exception {
        int code = Main.commandLine().execute("gui", "--arena", "lab", "--controller", "Braitenberg", "--seed", "3");
        if (code != 0) {
            fail("the gui command returned " + code);
        }
        w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        robot = new Robot();
        robot.setAutoDelay(20);
        input = new RobotInput(robot);
        robot.waitForIdle();
        Thread.sleep(500);
        for (String focus : new String[] {"arena", "consoleText"}) {
            Component target = focus.equals("arena") ? w.arenaComponent() : onEdt(() -> find(w.frame(), focus));
            KeyBindingsDriverSupport.clickCorner(input, target);
            String owner = onEdt(() -> {
                Component c = java.awt.KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner();
                return c == null ? "nothing" : c.getClass().getSimpleName() + "/" + c.getName();
            });
            System.out.println("focus in " + owner);
            press(KeyEvent.VK_F5, "F5 starts", () -> state() == PacedRunner.State.RUNNING);
            press(KeyEvent.VK_F6, "F6 pauses", () -> state() == PacedRunner.State.PAUSED);
            long before = w.runner().latest().timeNanos();
            press(KeyEvent.VK_F7, "F7 steps", () -> state() == PacedRunner.State.PAUSED && w.runner().latest().timeNanos() > before);
            press(KeyEvent.VK_SPACE, "Space resumes", () -> state() == PacedRunner.State.RUNNING);
            press(KeyEvent.VK_SPACE, "Space pauses", () -> state() == PacedRunner.State.PAUSED);
            press(KeyEvent.VK_F8, "F8 stops", () -> state() == PacedRunner.State.STOPPED);
            press(KeyEvent.VK_F10, "F10 reloads (the run is discarded)", () -> w.runner() == null);
        }
        System.out.println("KEYS OK");

        // Stopped at full speed: the console's note and the clock tell the same time. In lab without its
        // assignment, whose 600 s time limit a full-speed Braitenberg reaches in about a second.
        java.nio.file.Path openLab = java.nio.file.Files.createTempDirectory("keys").resolve("open-lab.arena");
        org.kheperasim.sim.arena.Arena lab = org.kheperasim.sim.arena.ArenaFormat.loadBundled("lab");
        org.kheperasim.sim.arena.ArenaFormat.save(lab.withAssignment(org.kheperasim.sim.arena.Assignment.NONE), openLab);
        SwingUtilities.invokeAndWait(() -> w.openArena(openLab));
        SwingUtilities.invokeAndWait(() -> {
            w.chooseSpeed(org.kheperasim.sim.run.PacedRunner.MAX_SPEED);
            w.action("start").actionPerformed(null);
        });
        // Well under way at full speed (a simulated minute), then stopped.
        long runUntil = System.nanoTime() + 60_000_000_000L;
        while (w.runner().latest().timeNanos() < 60_000_000_000L && System.nanoTime() < runUntil) {
            Thread.sleep(20);
        }
        // The F8 press above left a note of its own: wait for the next one.
        int before = onEdt(w::consoleText).split("Stopped at t = ", -1).length;
        SwingUtilities.invokeAndWait(() -> w.action("stop").actionPerformed(null));
        String note = null;
        long noteUntil = System.nanoTime() + 20_000_000_000L;
        while (note == null && System.nanoTime() < noteUntil) {
            Thread.sleep(50);
            String text = onEdt(w::consoleText);
            int at = text.lastIndexOf("Stopped at t = ");
            note = text.split("Stopped at t = ", -1).length == before ? null : text.substring(at + 15, text.indexOf(" s", at + 15));
        }
        String clock = String.format(java.util.Locale.ROOT, "%.3f", w.runner().latest().timeSeconds());
        if (note == null || !note.equals(clock)) {
            fail("stopped at full speed, the console says t = " + note + " s and the run's clock " + clock + " s");
        }
        System.out.println("stop note and clock agree at full speed: " + note + " s");
        SwingUtilities.invokeAndWait(() -> w.chooseSpeed(1));

        // Unsaved edits: Ctrl+Q asks first; Cancel keeps the window, Discard closes it.
        SwingUtilities.invokeAndWait(() -> w.model().apply(org.kheperasim.sim.edit.ArenaEdits.addCap(w.model().arena(), 900, 900)));
        for (String answer : new String[] {"Cancel", "Discard"}) {
            // The focus back in the window (after a dialog, without a window manager it may be nowhere).
            input.click(onEdt(() -> {
                Point o = w.arenaComponent().getLocationOnScreen();
                return new Point(o.x + 8, o.y + 8);
            }));
            input.keys(KeyEvent.VK_CONTROL, KeyEvent.VK_Q);
            Component button = null;
            long until = System.nanoTime() + 20_000_000_000L;
            while (button == null && System.nanoTime() < until) {
                Thread.sleep(50);
                button = onEdt(() -> {
                    for (java.awt.Window win : java.awt.Window.getWindows()) {
                        if (win instanceof javax.swing.JDialog d && d.isShowing() && "Unsaved changes".equals(d.getTitle())) {
                            return buttonLabelled(d, answer);
                        }
                    }
                    return null;
                });
            }
            if (button == null) {
                fail("Ctrl+Q with unsaved edits should ask first; no 'Unsaved changes' dialog with " + answer);
            }
            Component b = button;
            GuiE2EDriver.shot(robot, w, java.nio.file.Path.of(args.length > 0 ? args[0] : "target").resolve("keys-save-prompt.png"));
            SwingUtilities.invokeLater(() -> ((javax.swing.AbstractButton) b).doClick());
            // The prompt answered: its dialog gone, and with Discard the window too.
            long answered = System.nanoTime() + 20_000_000_000L;
            while (System.nanoTime() < answered && onEdt(() -> b.isShowing() || answer.equals("Discard") && w.frame().isDisplayable())) {
                Thread.sleep(20);
            }
            input.settle();
            boolean open = onEdt(() -> w.frame().isDisplayable());
            if (answer.equals("Cancel") && !open) {
                fail("Cancel in the save prompt closed the window");
            }
            if (answer.equals("Discard") && open) {
                fail("Discard in the save prompt did not close the window");
            }
            System.out.println("save prompt, " + answer + ": ok");
        }
        System.out.println("SAVE PROMPT OK");
        System.exit(0);
    }

    private static PacedRunner.State state() {
        PacedRunner r = w.runner();
        return r == null ? null : r.state();
    }

    private static void press(int key, String what, BooleanSupplier done) throws Exception {
        robot.keyPress(key);
        robot.keyRelease(key);
        robot.waitForIdle();
        long until = System.nanoTime() + 20_000_000_000L;
        while (!done.getAsBoolean() && System.nanoTime() < until) {
            Thread.sleep(20);
        }
        if (!done.getAsBoolean()) {
            fail(what + ": not done within 20 s; the run is " + state());
        }
        System.out.println(what + ": ok");
    }

    private static Component buttonLabelled(Container root, String label) {
        for (Component c : root.getComponents()) {
            if (c instanceof javax.swing.AbstractButton b && label.equals(b.getText())) {
                return c;
            }
            if (c instanceof Container k) {
                Component f = buttonLabelled(k, label);
                if (f != null) {
                    return f;
                }
            }
        }
        return null;
    }

    private static Component find(Container root, String name) {
        return KeyBindingsDriverSupport.find(root, name);
    }

    private static <T> T onEdt(java.util.function.Supplier<T> s) throws Exception {
        return KeyBindingsDriverSupport.onEdt(s);
    }

    private static void fail(String why) {
        System.out.println("FAIL: " + why);
        try {
            System.out.println(onEdt(w::consoleText));
        } catch (Exception e) {
            System.out.println("(no console: " + e + ")");
        }
        System.exit(1);
    }
}
