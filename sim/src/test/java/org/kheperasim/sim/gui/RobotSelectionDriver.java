package org.kheperasim.sim.gui;

import java.awt.Point;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.cli.Main;
import org.kheperasim.sim.engine.view.RobotView;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * Runs in a child JVM under Xvfb (see {@link RobotSelectionTest}): a run of two robots in the
 * window; a click on the second robot makes the sensor panel show it. Arguments: output folder,
 * arena file.
 */
public final class RobotSelectionDriver {
    private RobotSelectionDriver() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        int code = Main.commandLine().execute("gui", "--arena", args[1], "--controller", "Braitenberg", "--seed", "3");
        if (code != 0) {
            fail("the gui command returned " + code);
        }
        MainWindow w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        Robot robot = new Robot();
        robot.setAutoDelay(15);
        robot.waitForIdle();
        SwingUtilities.invokeAndWait(() -> w.action("start").actionPerformed(null));
        runPast(w, 2);
        SwingUtilities.invokeAndWait(() -> w.action("pause").actionPerformed(null));
        Thread.sleep(300);
        robot.waitForIdle();
        RobotView before = onEdt(w::shownRobot);
        if (before == null || before.id() != 0) {
            fail("the sensor panel should show robot 0 at first, shows " + before);
        }
        GuiE2EDriver.shot(robot, w, out.resolve("robots-1-first-selected.png"));
        Snapshot paused = w.runner().latest();
        RobotView second = paused.robots().get(1);
        Point p = onEdt(() -> {
            Point o = w.arenaComponent().getLocationOnScreen();
            return new Point(o.x + (int) StrictMath.round(w.view().sx(second.x())),
                    o.y + (int) StrictMath.round(w.view().sy(second.y())));
        });
        robot.mouseMove(p.x, p.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.waitForIdle();
        Thread.sleep(300);
        RobotView after = onEdt(w::shownRobot);
        if (after == null || after.id() != 1) {
            fail("a click on robot 1 at " + second.x() + ", " + second.y() + " should select it; the panel shows " + after);
        }
        int edits = onEdt(() -> w.model().arena().robots().size());
        GuiE2EDriver.shot(robot, w, out.resolve("robots-2-second-selected.png"));
        System.out.printf(Locale.ROOT, "panel showed robot 0 at (%.1f, %.1f), now robot 1 at (%.1f, %.1f); arena still has %d robots%n",
                before.x(), before.y(), after.x(), after.y(), edits);
        System.out.println("SELECTION OK");

        // Robot 1 (selected) gets a controller of its own; the next run shows it.
        SwingUtilities.invokeAndWait(() -> {
            javax.swing.JComboBox<?> box = (javax.swing.JComboBox<?>) find(w.frame(), "controller");
            box.setSelectedItem("WallFollower");
            w.action("assignRobot").actionPerformed(null);
            box.setSelectedItem("Braitenberg");
            w.action("start").actionPerformed(null);
        });
        Snapshot mixed = runPast(w, 0.5);
        if (mixed == null || !mixed.robots().get(0).name().equals("Braitenberg#0")
                || !mixed.robots().get(1).name().equals("WallFollower#1")) {
            fail("robot 1 should run WallFollower and robot 0 Braitenberg: " + (mixed == null ? "no run"
                    : mixed.robots().get(0).name() + ", " + mixed.robots().get(1).name()));
        }
        System.out.println("PER-ROBOT CONTROLLER OK");

        // Serving the arena from the window: each robot on its own port; two clients drive them together.
        SwingUtilities.invokeAndWait(() -> w.action("stop").actionPerformed(null));
        SwingUtilities.invokeAndWait(() -> w.action("serve").actionPerformed(null));
        java.util.List<org.kheperasim.sim.serve.ProtocolServer> servers = onEdt(w::servers);
        if (servers.size() != 2) {
            fail("serving a two-robot arena should make two servers, made " + servers.size());
        }
        try (java.net.Socket a = new java.net.Socket(java.net.InetAddress.getLoopbackAddress(), servers.get(0).port());
                java.net.Socket b = new java.net.Socket(java.net.InetAddress.getLoopbackAddress(), servers.get(1).port())) {
            a.getOutputStream().write("D,8,8\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
            b.getOutputStream().write("D,8,8\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
            long until = System.nanoTime() + 60_000_000_000L;
            boolean met = false;
            while (!met && System.nanoTime() < until) {
                Thread.sleep(100);
                Snapshot served = onEdt(w::snapshot);
                met = served != null && served.robots().size() == 2
                        && served.robots().get(0).contact() != org.kheperasim.sim.engine.view.Contact.NONE
                        && served.robots().get(1).contact() != org.kheperasim.sim.engine.view.Contact.NONE;
            }
            GuiE2EDriver.shot(robot, w, out.resolve("robots-3-served-and-met.png"));
            if (!met) {
                fail("the two served robots, driven at each other by two clients, did not meet within 60 s");
            }
            // The panel shows what the served robot (robot 1, selected) last reported to its client.
            java.io.BufferedReader replies = new java.io.BufferedReader(new java.io.InputStreamReader(b.getInputStream(),
                    java.nio.charset.StandardCharsets.US_ASCII));
            b.getOutputStream().write("N\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
            String reply = replies.readLine();
            while (reply != null && !reply.startsWith("n,")) {
                reply = replies.readLine();
            }
            String told = reply;
            long until3 = System.nanoTime() + 30_000_000_000L;
            String shown = null;
            while (System.nanoTime() < until3) {
                RobotView v = onEdt(w::shownRobot);
                shown = v == null ? null : "n," + java.util.Arrays.stream(v.proximity()).mapToObj(String::valueOf)
                        .collect(java.util.stream.Collectors.joining(","));
                if (shown != null && shown.equals(told)) {
                    break;
                }
                Thread.sleep(50);
            }
            if (told == null || !told.equals(shown)) {
                fail("the sensor panel should show what robot 1 last told its client, " + told + "; it shows " + shown);
            }
            System.out.println("served robot 1 told its client " + told + "; the panel shows the same");
        }
        System.out.println("SERVE OK");

        // Another arena: the robots of the last one kept their own controllers; the new one's do not.
        SwingUtilities.invokeAndWait(() -> w.action("serve").actionPerformed(null));
        Path other = out.resolve("other.arena");
        java.nio.file.Files.writeString(other, java.nio.file.Files.readString(Path.of(args[1])).replaceFirst("(?m)^name .*$",
                "name other"));
        SwingUtilities.invokeAndWait(() -> {
            w.openArena(other);
            w.action("start").actionPerformed(null);
        });
        Snapshot fresh = runPast(w, 0.5);
        if (fresh == null || !fresh.robots().get(1).name().equals("Braitenberg#1")) {
            fail("in another arena robot 1 should run the chosen Braitenberg, not the last arena's WallFollower: "
                    + (fresh == null ? "no run" : fresh.robots().get(1).name()));
        }
        System.out.println("OTHER ARENA OK");
        SwingUtilities.invokeAndWait(() -> w.action("close").actionPerformed(null));
        System.exit(0);
    }

    /** @return the window's run once it has passed {@code seconds} of simulated time (the latest seen after 60 s of waiting), or null */
    private static Snapshot runPast(MainWindow w, double seconds) throws InterruptedException {
        long deadline = System.nanoTime() + 60_000_000_000L;
        Snapshot s = null;
        while (System.nanoTime() < deadline) {
            s = w.runner() == null ? null : w.runner().latest();
            if (s != null && s.timeSeconds() >= seconds) {
                break;
            }
            Thread.sleep(20);
        }
        return s;
    }

    private static <T> T onEdt(java.util.function.Supplier<T> s) throws Exception {
        AtomicReference<T> ref = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> ref.set(s.get()));
        return ref.get();
    }

    private static java.awt.Component find(java.awt.Container root, String name) {
        for (java.awt.Component c : root.getComponents()) {
            if (name.equals(c.getName())) {
                return c;
            }
            if (c instanceof java.awt.Container k) {
                java.awt.Component f = find(k, name);
                if (f != null) {
                    return f;
                }
            }
        }
        return null;
    }

    private static void fail(String why) {
        System.out.println("FAIL: " + why);
        System.exit(1);
    }
}
