package org.kheperasim.sim.gui;

import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.check;

import java.awt.Color;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.image.BufferedImage;
import java.io.BufferedReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JSlider;
import javax.swing.SwingUtilities;
import javax.swing.plaf.basic.BasicSliderUI;
import org.kheperasim.sim.arena.ArenaFormat;
import org.kheperasim.sim.cli.Main;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.run.Simulation;

/**
 * Runs in a child JVM under Xvfb (see {@link ReplayWindowTest}): a one-hour run recording is opened
 * in the window, the timeline dragged with the mouse to the middle, Play pressed, the speed raised,
 * Rewind pressed; each time the robot drawn is checked against the trace, on screen and in the
 * view's snapshot. Prints the figures: trace size per simulated minute, time to open, frame rates.
 * An edit made before the recording was opened comes back with Close replay, still unsaved, and
 * Ctrl+Q then asks before it is lost. Arguments: output folder.
 */
public final class ReplayWindowDriver {
    private static final double SECONDS = 3600;

    private ReplayWindowDriver() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        Path rec = Files.createDirectories(out.resolve("replay-recording"));
        long t0 = System.nanoTime();
        Simulation.builder().arena("lab").controller("Braitenberg").seed(5).seconds(SECONDS)
                .trace(rec.resolve("run.trace")).sampleMillis(50).run();
        ArenaFormat.save(ArenaFormat.loadBundled("lab"), rec.resolve("start.arena"));
        long bytes = Files.size(rec.resolve("run.trace"));
        System.out.printf(Locale.ROOT, "FIGURE trace of %.0f s at 50 ms: %d bytes, %.1f kB per simulated minute (made in %.1f s)%n",
                SECONDS, bytes, bytes / 1024.0 / (SECONDS / 60), (System.nanoTime() - t0) / 1e9);
        int code = Main.commandLine().execute("gui", "--arena", "lab", "--controller", "Braitenberg", "--seed", "1");
        check(code == 0, "the gui command returned " + code);
        MainWindow w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        Robot robot = new Robot();
        robot.setAutoDelay(15);
        RobotInput input = new RobotInput(robot);
        input.settle();
        // An edit not saved yet: opening a recording keeps it (a Discard asked for here once lost it, see the end).
        SwingUtilities.invokeAndWait(() -> w.model().apply(org.kheperasim.sim.edit.ArenaEdits.addCap(w.model().arena(), 300, 900)));
        org.kheperasim.sim.arena.Arena edited = onEdt(() -> w.model().arena());
        long open0 = System.nanoTime();
        boolean[] opened = {false};
        SwingUtilities.invokeLater(() -> opened[0] = w.openRecording(rec));
        // Should the window still ask about the unsaved edit, answer as the student did: Discard.
        long askUntil = System.nanoTime() + 3_000_000_000L;
        while (!onEdt(() -> w.player().open()) && System.nanoTime() < askUntil) {
            Thread.sleep(50);
            java.awt.Component discard = onEdt(() -> unsavedPrompt("Discard"));
            if (discard != null) {
                System.out.println("the window asked about the unsaved edit; Discard");
                SwingUtilities.invokeLater(() -> ((javax.swing.AbstractButton) discard).doClick());
            }
        }
        long openUntil = System.nanoTime() + 30_000_000_000L;
        while (!onEdt(() -> w.player().open()) && System.nanoTime() < openUntil) {
            Thread.sleep(20);
        }
        System.out.printf(Locale.ROOT, "FIGURE opening the one-hour recording took %.0f ms (read, parse, show)%n",
                (System.nanoTime() - open0) / 1e6);
        check(onEdt(() -> w.player().open()), "the recording did not open:\n" + w.consoleText());
        input.settle();

        // Scrub: drag the timeline's thumb from the start to the middle with the mouse.
        JSlider timeline = (JSlider) KeyBindingsDriverSupport.find(w.frame(), "replay.timeline");
        check(timeline != null && timeline.isShowing(), "the replay bar's timeline is not shown");
        Point[] ends = onEdt(() -> {
            BasicSliderUI ui = (BasicSliderUI) timeline.getUI();
            Point o = timeline.getLocationOnScreen();
            int y = o.y + timeline.getHeight() / 2;
            int x0 = -1;
            int xm = -1;
            for (int x = 0; x < timeline.getWidth(); x++) {
                int v = ui.valueForXPosition(x);
                if (x0 < 0 && v > 0) {
                    x0 = x - 1;
                }
                if (xm < 0 && v >= ReplayBar.TICKS / 2) {
                    xm = x;
                }
            }
            return new Point[] {new Point(o.x + x0, y), new Point(o.x + xm, y)};
        });
        input.move(ends[0]);
        input.press();
        System.out.println("timeline " + onEdt(() -> timeline.getBounds() + " on screen at " + timeline.getLocationOnScreen()
                + " ui " + timeline.getUI().getClass().getName()) + "; press at " + ends[0] + ", value " + onEdt(timeline::getValue)
                + ", adjusting " + onEdt(timeline::getValueIsAdjusting) + "; drag to " + ends[1]);
        for (int k = 1; k <= 10; k++) {
            input.move(new Point(ends[0].x + (ends[1].x - ends[0].x) * k / 10, ends[0].y));
        }
        // As a person scrubs: look where the thumb went and move on until it shows the middle.
        int x = ends[1].x;
        int width = onEdt(timeline::getWidth);
        for (int k = 0; k < 30; k++) {
            int v = onEdt(timeline::getValue);
            if (StrictMath.abs(v - ReplayBar.TICKS / 2) < ReplayBar.TICKS / 100) {
                break;
            }
            int dx = (int) StrictMath.round((ReplayBar.TICKS / 2.0 - v) * width / ReplayBar.TICKS);
            x += dx == 0 ? Integer.signum(ReplayBar.TICKS / 2 - v) : dx;
            input.move(new Point(x, ends[0].y));
        }
        System.out.println("thumb released at value " + onEdt(timeline::getValue) + " of " + ReplayBar.TICKS);
        input.release();
        waitUntil("the cursor follows the timeline's thumb", () -> StrictMath.abs(w.player().cursor()
                - timeline.getValue() * SECONDS / ReplayBar.TICKS) < SECONDS / ReplayBar.TICKS);
        double middle = onEdt(() -> w.player().cursor());
        double bySlider = onEdt(timeline::getValue) * SECONDS / ReplayBar.TICKS;
        check(StrictMath.abs(middle - bySlider) < SECONDS / ReplayBar.TICKS, "the cursor " + middle
                + " s should follow the timeline's thumb, " + bySlider + " s");
        check(StrictMath.abs(middle - SECONDS / 2) < SECONDS * 0.02, "the drag should put the cursor near the middle, "
                + SECONDS / 2 + " s; it is at " + middle + " s");
        checkDrawnRobot(robot, w, rec.resolve("run.trace"), out.resolve("replay-1-middle.png"));
        System.out.printf(Locale.ROOT, "scrubbed to %.2f s%n", middle);

        // Play at x1 for a while: time moves on, the frame rate is measured.
        click(input, (JButton) KeyBindingsDriverSupport.find(w.frame(), "replay.play"));
        Thread.sleep(2000);
        double fps1 = onEdt(w::fps);
        double played = onEdt(() -> w.player().cursor());
        check(onEdt(() -> w.player().playing()), "Play should play");
        check(played > middle + 1 && played < middle + 60, "after 2 s at x1 the cursor should be about 2 s on: "
                + middle + " -> " + played);
        GuiE2EDriver.shot(robot, w, out.resolve("replay-2-playing.png"));
        SwingUtilities.invokeAndWait(() -> ((JComboBox<?>) KeyBindingsDriverSupport.find(w.frame(), "replay.speed"))
                .setSelectedIndex(ReplayPlayer.SPEEDS.length - 1));
        Thread.sleep(1500);
        double fpsFast = onEdt(w::fps);
        double fast = onEdt(() -> w.player().cursor());
        check(fast > played + 30, "at x64 the cursor should race: " + played + " -> " + fast);
        System.out.printf(Locale.ROOT, "FIGURE replay frame rate: %.0f fps at x1, %.0f fps at x64%n", fps1, fpsFast);

        // Rewind: back to the start, the robot at its first sample.
        click(input, (JButton) KeyBindingsDriverSupport.find(w.frame(), "replay.play"));
        check(!onEdt(() -> w.player().playing()), "the second press of Play pauses");
        click(input, (JButton) KeyBindingsDriverSupport.find(w.frame(), "replay.rewind"));
        waitUntil("Rewind takes the cursor to the start", () -> w.player().cursor() == 0);
        double rewound = onEdt(() -> w.player().cursor());
        check(rewound == 0, "Pause, then Rewind, should leave the cursor at the start: " + rewound);
        checkDrawnRobot(robot, w, rec.resolve("run.trace"), out.resolve("replay-3-rewound.png"));

        // The plot over the whole run, exported.
        SwingUtilities.invokeAndWait(() -> w.plot().chooseSpan(3));
        Thread.sleep(300);
        SwingUtilities.invokeAndWait(() -> {
            w.plot().exportTo(out.resolve("replay-plot.csv"), true);
            w.plot().exportTo(out.resolve("replay-plot.png"), false);
        });
        long rows = Files.lines(out.resolve("replay-plot.csv")).count();
        System.out.println("plot CSV rows (with the header): " + rows);
        System.out.println("REPLAY OK");

        // Close replay: the arena comes back with its edit, still marked unsaved, and Ctrl+Q asks before it is lost.
        SwingUtilities.invokeAndWait(() -> w.action("closeReplay").actionPerformed(null));
        check(onEdt(() -> w.model().arena()).equals(edited), "Close replay brings back the edited arena");
        check(onEdt(() -> w.model().dirty()), "the edit is still marked unsaved after Close replay");
        check(onEdt(() -> w.frame().getTitle()).contains(" *"), "the title marks it unsaved: " + onEdt(() -> w.frame().getTitle()));
        input.click(onEdt(() -> {
            Point o = w.arenaComponent().getLocationOnScreen();
            return new Point(o.x + 8, o.y + 8);
        }));
        input.keys(java.awt.event.KeyEvent.VK_CONTROL, java.awt.event.KeyEvent.VK_Q);
        java.awt.Component cancel = null;
        long until = System.nanoTime() + 20_000_000_000L;
        while (cancel == null && System.nanoTime() < until && onEdt(() -> w.frame().isDisplayable())) {
            Thread.sleep(50);
            cancel = onEdt(() -> unsavedPrompt("Cancel"));
        }
        check(cancel != null, "Ctrl+Q with the edit back must ask Save, Discard or Cancel; the window "
                + (onEdt(() -> w.frame().isDisplayable()) ? "did not ask" : "closed and lost it"));
        java.awt.Component c = cancel;
        SwingUtilities.invokeLater(() -> ((javax.swing.AbstractButton) c).doClick());
        Thread.sleep(300);
        check(onEdt(() -> w.frame().isDisplayable()), "Cancel keeps the window");
        System.out.println("UNSAVED EDITS KEPT OK");
        System.exit(0);
    }

    /** @return the button labelled {@code label} of the showing "Unsaved changes" dialog, or null */
    private static java.awt.Component unsavedPrompt(String label) {
        for (java.awt.Window win : java.awt.Window.getWindows()) {
            if (win instanceof javax.swing.JDialog d && d.isShowing() && "Unsaved changes".equals(d.getTitle())) {
                return button(d, label);
            }
        }
        return null;
    }

    private static java.awt.Component button(java.awt.Container root, String label) {
        for (java.awt.Component c : root.getComponents()) {
            if (c instanceof javax.swing.AbstractButton b && label.equals(b.getText())) {
                return c;
            }
            if (c instanceof java.awt.Container k) {
                java.awt.Component f = button(k, label);
                if (f != null) {
                    return f;
                }
            }
        }
        return null;
    }

    /** The view draws the robot where the trace has it at the cursor: in the snapshot and on screen. */
    private static void checkDrawnRobot(Robot robot, MainWindow w, Path trace, Path shot) throws Exception {
        double cursor = onEdt(() -> w.player().cursor());
        RobotView shown = onEdt(w::shownRobot);
        String[] line = lineAt(trace, cursor);
        double x = Double.parseDouble(line[2]);
        double y = Double.parseDouble(line[3]);
        check(StrictMath.abs(shown.x() - x) < 1e-3 && StrictMath.abs(shown.y() - y) < 1e-3, "at " + cursor
                + " s the trace has the robot at (" + x + ", " + y + "), the view at (" + shown.x() + ", " + shown.y() + ")");
        // Two frames painted since: the screen shows this moment.
        long frames = onEdt(() -> ((ArenaView) w.arenaComponent()).frames());
        waitUntil("the view paints", () -> ((ArenaView) w.arenaComponent()).frames() >= frames + 2);
        GuiE2EDriver.shot(robot, w, shot);
        Point p = onEdt(() -> {
            Point o = w.arenaComponent().getLocationOnScreen();
            return new Point(o.x + (int) StrictMath.round(w.view().sx(x)), o.y + (int) StrictMath.round(w.view().sy(y)));
        });
        double r = onEdt(() -> w.view().scale()) * 27.5 * 0.6;
        BufferedImage img = robot.createScreenCapture(new Rectangle(p.x - (int) r, p.y - (int) r, 2 * (int) r + 1, 2 * (int) r + 1));
        int green = 0;
        int all = 0;
        for (int i = 0; i < img.getWidth(); i++) {
            for (int j = 0; j < img.getHeight(); j++) {
                Color c = new Color(img.getRGB(i, j));
                all++;
                if (StrictMath.abs(c.getRed() - 0x2E) < 30 && StrictMath.abs(c.getGreen() - 0x8B) < 30 && StrictMath.abs(c.getBlue() - 0x57) < 30) {
                    green++;
                }
            }
        }
        check(green > all / 3, "the robot's body colour should fill the square around (" + x + ", " + y + ") on screen; "
                + green + " of " + all + " pixels are its green (see " + shot + ")");
        System.out.printf(Locale.ROOT, "at %.2f s the robot is drawn at (%.3f, %.3f) as the trace says; %d%% body pixels%n",
                cursor, x, y, 100 * green / all);
    }

    /** @return the trace's robot line of the last sample at or before {@code t} */
    private static String[] lineAt(Path trace, double t) throws Exception {
        String[] best = null;
        try (BufferedReader in = Files.newBufferedReader(trace)) {
            for (String l = in.readLine(); l != null; l = in.readLine()) {
                if (l.startsWith("#") || l.contains(" cap ")) {
                    continue;
                }
                String[] f = l.split(" ");
                if (Double.parseDouble(f[0]) > t + 1e-9) {
                    break;
                }
                best = f;
            }
        }
        return best;
    }

    private static void click(RobotInput input, JButton b) throws Exception {
        check(b != null, "a replay button is missing");
        input.click(onEdt(() -> {
            Point o = b.getLocationOnScreen();
            return new Point(o.x + b.getWidth() / 2, o.y + b.getHeight() / 2);
        }));
    }

    /** Waits, asking on the event thread, until {@code done}; the check fails after 30 s. */
    private static void waitUntil(String what, java.util.function.BooleanSupplier done) throws Exception {
        long until = System.nanoTime() + 30_000_000_000L;
        while (!onEdt(done::getAsBoolean) && System.nanoTime() < until) {
            Thread.sleep(10);
        }
        check(onEdt(done::getAsBoolean), what + ": not within 30 s");
    }

    private static <T> T onEdt(java.util.function.Supplier<T> s) throws Exception {
        AtomicReference<T> ref = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> ref.set(s.get()));
        return ref.get();
    }

}
