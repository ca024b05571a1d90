package org.kheperasim.sim.gui;

import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.check;
import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.onEdt;

import java.awt.Robot;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.cli.Main;
import org.kheperasim.sim.engine.view.Snapshot;

/**
 * Runs in a child JVM under Xvfb (see {@link GuiRobotFileTest}): {@code gui --robot-file epuck} on an
 * arena of an untyped robot line and a {@code khepera2} one opens with an e-puck and a Khepera II, and
 * the run it starts drives those. Argument: output folder.
 */
public final class GuiRobotFileDriver {
    private GuiRobotFileDriver() {
    }

    public static void main(String[] args) throws Exception {
        Path arena = Files.writeString(Path.of(args[0]).resolve("gui-robot-file.arena"), "khepera-arena 1\nname two\n"
                + "size 1000 1000\nrobot 250 500 0\nrobot 750 500 180 khepera2\n"
                + "wall 0 4 1000 4 8\nwall 0 996 1000 996 8\nwall 4 0 4 1000 8\nwall 996 0 996 1000 8\n");
        int code = Main.commandLine().execute("gui", "--arena", arena.toString(), "--robot-file", "epuck",
                "--controller", "Braitenberg", "--seed", "1");
        check(code == 0, "the gui command returned " + code);
        MainWindow w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        String types = onEdt(() -> w.model().arena().robotType(0).name() + " " + w.model().arena().robotType(1).name());
        check(types.equals("epuck khepera2"), "the window's robots should be epuck khepera2, they are " + types);
        System.out.println("window robots: " + types);

        SwingUtilities.invokeAndWait(w::start);
        long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(90);
        Snapshot s = null;
        while ((s == null || s.timeSeconds() < 1) && System.nanoTime() < until) {
            Thread.sleep(20);
            s = w.runner() == null ? null : w.runner().latest();
        }
        check(s != null && s.timeSeconds() >= 1, "the run did not reach 1 s in 90 s: " + onEdt(w::consoleText));
        String ran = s.robots().get(0).type().name() + " " + s.robots().get(1).type().name();
        check(ran.equals("epuck khepera2"), "the run's robots should be epuck khepera2, they are " + ran);
        System.out.println("run robots: " + ran);
        SwingUtilities.invokeAndWait(() -> w.action("pause").actionPerformed(null));
        Thread.sleep(300);
        GuiE2EDriver.shot(new Robot(), w, Path.of(args[0]).resolve("gui-robot-file.png"));
        System.out.println("ROBOT FILE OK");
        System.exit(0);
    }
}
