package org.kheperasim.sim.gui;

import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.run.PacedRunner;
import org.kheperasim.sim.run.RunResult;
import org.kheperasim.sim.run.Simulation;

/**
 * Measures the window: start-up time to a painted window, frames per second at ×1 with every
 * panel on, and the engine's speed at "as fast as possible" with the window open against the same
 * run headless. Prints figures; asserts nothing.
 */
public final class GuiBench {
    private GuiBench() {
    }

    /**
     * @param out where the figures go
     * @param seconds real seconds for each measurement
     * @throws Exception if the window cannot be opened
     */
    public static void run(PrintStream out, double seconds) throws Exception {
        long jvmStart = ManagementFactory.getRuntimeMXBean().getStartTime();
        MainWindow w = GuiLauncher.launch(GuiOptions.defaults()).get(30, TimeUnit.SECONDS);
        ArenaView view = (ArenaView) w.arenaComponent();
        while (view.frames() == 0) {
            Thread.sleep(5);
        }
        long painted = System.currentTimeMillis();
        out.printf(Locale.ROOT,
                "start-up: %.2f s from JVM start to the first painted frame of the window (maze, WallFollower)%n",
                (painted - jvmStart) / 1000.0);
        SwingUtilities.invokeAndWait(() -> {
            w.setSeed(1);
            w.action("start").actionPerformed(null);
        });
        Thread.sleep(1000);
        long f0 = view.frames();
        long t0 = System.nanoTime();
        double sim0 = w.runner().latest().timeSeconds();
        Thread.sleep((long) (seconds * 1000));
        long f1 = view.frames();
        long t1 = System.nanoTime();
        double sim1 = w.runner().latest().timeSeconds();
        out.printf(Locale.ROOT,
                "x1 with every panel on (beams, trail, grid, sensor panel, plot, console): %.1f frames/s;"
                + " simulated %.2f s in %.2f s (%.3fx)%n", (f1 - f0) * 1e9 / (t1 - t0), sim1 - sim0, (t1 - t0) / 1e9,
                (sim1 - sim0) / ((t1 - t0) / 1e9));

        PacedRunner r = w.runner();
        SwingUtilities.invokeAndWait(() -> w.chooseSpeed(PacedRunner.MAX_SPEED));
        Thread.sleep(500);
        AtomicLong frames = new AtomicLong(view.frames());
        t0 = System.nanoTime();
        sim0 = r.latest().timeSeconds();
        Thread.sleep((long) (seconds * 1000));
        t1 = System.nanoTime();
        sim1 = r.latest().timeSeconds();
        double windowSpeed = (sim1 - sim0) / ((t1 - t0) / 1e9);
        out.printf(Locale.ROOT,
                "as fast as possible, window open: %.0fx real time (%.1f frames/s meanwhile)%n", windowSpeed,
                (view.frames() - frames.get()) * 1e9 / (t1 - t0));
        SwingUtilities.invokeAndWait(() -> w.action("close").actionPerformed(null));
        Thread.sleep(300);

        double simSeconds = StrictMath.max(60, StrictMath.rint(sim1 - sim0));
        RunResult headless =
                Simulation.builder().arena("maze").controller("WallFollower").seed(1).seconds(simSeconds).run();
        out.printf(Locale.ROOT, "headless, same run: %.0fx real time (%.0f s simulated in %.2f s)%n",
                headless.realTimeFactor(),
                headless.simulatedSeconds(), headless.wallSeconds());
        out.printf(Locale.ROOT, "the window costs %.0f%% of the engine's speed%n",
                100 * (1 - windowSpeed / headless.realTimeFactor()));
    }
}
