package org.kheperasim.sim.gui;

import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.onEdtQuiet;

import java.awt.Robot;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;
import org.kheperasim.sim.cli.Main;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.run.PacedRunner;

/**
 * Runs in a child JVM under Xvfb (see {@link FirstControllerLoopTest}): a newcomer's first loop of
 * write, compile, run, repeat. It opens MyFirst.java in the window (what Controller > Open .java
 * does after the file dialog), runs it with F5, breaks the file and presses F10 (the console names
 * the line) and F5 (nothing runs: the status bar says the file does not compile), then changes the
 * behaviour, presses F10 and F5, and sees the new behaviour; last, changes it back and presses F9 and
 * F5 without F10: Start compiles the changed file and runs it.
 */
public final class FirstControllerLoopDriver {
    private static Robot robot;
    /** One for the driver: each registers a listener for the window's input events. */
    private static RobotInput input;
    private static MainWindow w;

    private FirstControllerLoopDriver() {
    }

    public static void main(String[] args) throws Exception {
        Path target = Path.of(args[0]);
        Path source = Path.of(args[1]);
        String original = Files.readString(source);
        int code = Main.commandLine().execute("gui", "--arena", "lab", "--seed", "1");
        check(code == 0, "the gui command returned " + code);
        w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        robot = new Robot();
        robot.setAutoDelay(20);
        input = new RobotInput(robot);
        robot.waitForIdle();

        // Compile and run.
        check(onEdt(() -> w.compileAndUse(source)), "MyFirst.java compiles in the window:\n" + onEdt(w::consoleText));
        check("MyFirst".equals(onEdt(w::controllerName)), "MyFirst is the chosen controller, not " + onEdt(w::controllerName));
        focusArena();
        onEdt(() -> {
            w.chooseSpeed(PacedRunner.MAX_SPEED);
            return null;
        });
        runFor(20);
        RobotView after = w.runner().latest().robots().get(0);
        // How far it drove since the run began (not how far from the start: it may have come back).
        double moved = after.distanceMm();
        check(moved > 200, "MyFirst drives off: " + Math.round(moved) + " mm driven in at least 20 s");
        GuiE2EDriver.shot(robot, w, target.resolve("first-1-running.png"));
        System.out.printf("RUN OK: MyFirst drove %.0f mm by %.1f simulated s%n", moved, w.runner().latest().timeSeconds());

        // Repeat, with a mistake: the compiler's message names the file and the line.
        Files.writeString(source, original.replace("setSpeeds(5, 5);", "setSpeeds(5, 5)"));
        press(KeyEvent.VK_F10, "F10 recompiles", () -> onEdtQuiet(w::consoleText).contains("compiling MyFirst.java failed"));
        String console = onEdt(w::consoleText);
        int line = lineOf(original, "setSpeeds(5, 5);");
        check(console.contains("MyFirst.java:" + line + ":"), "the console names line " + line + ":\n" + console);
        System.out.println("ERROR OK: the console names MyFirst.java:" + line);

        // F5 now runs nothing: not the last version that compiled, which the student would take for the file they see.
        robot.keyPress(KeyEvent.VK_F5);
        robot.keyRelease(KeyEvent.VK_F5);
        robot.waitForIdle();
        Thread.sleep(1000);
        check(w.runner() == null || w.runner().state() != PacedRunner.State.RUNNING,
                "F5 after a failed compile must not run the version that compiled before");
        String refused = onEdt(() -> w.status().message());
        check(onEdt(() -> w.status().messageRed()) && refused.contains("MyFirst.java does not compile: MyFirst.java:" + line + ":"),
                "the status bar says, in red, that MyFirst.java does not compile and where: " + refused);
        System.out.println("STALE REFUSED OK: " + refused);

        // Repeat, with a change: spin on the spot instead of driving ahead.
        Files.writeString(source, original.replace("setSpeeds(5, 5);", "setSpeeds(-3, 3);"));
        press(KeyEvent.VK_F10, "F10 recompiles the fix", () -> onEdtQuiet(w::consoleText).contains("Controller MyFirst loaded"));
        runFor(20);
        RobotView spun = w.runner().latest().robots().get(0);
        org.kheperasim.sim.arena.Pose home = onEdt(() -> w.model().arena().robots().get(0));
        double drift = Math.hypot(spun.x() - home.x(), spun.y() - home.y());
        check(drift < 30, "the changed MyFirst spins on the spot: " + Math.round(drift) + " mm from the start");
        int left = spun.encoderLeft();
        int right = spun.encoderRight();
        check(left < -100 && right > 100, "and turns on the spot: encoders " + left + ", " + right);
        GuiE2EDriver.shot(robot, w, target.resolve("first-2-changed.png"));
        System.out.printf("REPEAT OK: the changed MyFirst stayed within %.0f mm%n", drift);

        // Change it back, Reset and Start without F10: the run is the file as it is now, compiled again.
        Files.writeString(source, original);
        press(KeyEvent.VK_F9, "F9 resets", () -> w.runner() == null);
        runFor(20);
        check(onEdt(w::consoleText).contains("MyFirst.java changed since it was compiled: compiling it again for this run"),
                "Start says it compiles the changed file:\n" + onEdt(w::consoleText));
        double again = w.runner().latest().robots().get(0).distanceMm();
        check(again > 200, "the original MyFirst drives off again: " + Math.round(again) + " mm");
        System.out.printf("START COMPILES OK: %.0f mm%n", again);
        System.exit(0);
    }

    /**
     * Press F5, let the run go to at least {@code seconds} of simulated time, and pause it (F6); at full
     * speed a quick controller may reach the arena's time limit first, where the run ends by itself.
     */
    private static void runFor(double seconds) throws Exception {
        press(KeyEvent.VK_F5, "F5 starts", () -> w.runner() != null && (w.runner().state() == PacedRunner.State.RUNNING
                || w.runner().state() == PacedRunner.State.TIME_UP));
        long until = System.nanoTime() + 60_000_000_000L;
        while (w.runner().latest().timeSeconds() < seconds && System.nanoTime() < until) {
            Thread.sleep(20);
        }
        check(w.runner().latest().timeSeconds() >= seconds, "the run reached " + seconds + " s");
        if (w.runner().state() != PacedRunner.State.TIME_UP) {
            press(KeyEvent.VK_F6, "F6 pauses", () -> w.runner().state() == PacedRunner.State.PAUSED
                    || w.runner().state() == PacedRunner.State.TIME_UP);
        }
    }

    private static void focusArena() throws Exception {
        KeyBindingsDriverSupport.clickCorner(input, w.arenaComponent());
    }

    private static int lineOf(String text, String what) {
        return text.substring(0, text.indexOf(what)).split("\n", -1).length;
    }

    private static void press(int key, String what, BooleanSupplier done) throws Exception {
        robot.keyPress(key);
        robot.keyRelease(key);
        robot.waitForIdle();
        long until = System.nanoTime() + 30_000_000_000L;
        while (!done.getAsBoolean() && System.nanoTime() < until) {
            Thread.sleep(20);
        }
        check(done.getAsBoolean(), what + ": not done within 30 s");
        System.out.println(what + ": ok");
    }

    private static <T> T onEdt(Supplier<T> s) throws Exception {
        return KeyBindingsDriverSupport.onEdt(s);
    }

    private static void check(boolean ok, String why) {
        if (!ok) {
            System.out.println("FAIL: " + why);
            if (w != null) {
                System.out.println("status bar: " + onEdtQuiet(() -> w.status().message()) + "\nconsole:\n"
                        + onEdtQuiet(w::consoleText));
            }
            System.exit(1);
        }
    }
}
