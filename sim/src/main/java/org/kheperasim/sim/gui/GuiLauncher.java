package org.kheperasim.sim.gui;

import java.awt.GraphicsEnvironment;
import java.util.concurrent.CompletableFuture;
import javax.swing.SwingUtilities;

/** Opens the simulator's window: the command line's entry point into the GUI. */
public final class GuiLauncher {
    private static final System.Logger LOG = System.getLogger(GuiLauncher.class.getName());

    private static volatile CompletableFuture<MainWindow> last = new CompletableFuture<>();
    /**
     * The JDK's preferences, where the window keeps its size and recent files, log an INFO line
     * ("Created user preferences directory") on a first launch that means nothing to a student: only
     * their warnings are shown. Held here, as a logger nobody holds may be collected with its level.
     */
    private static final java.util.logging.Logger PREFS_LOG = java.util.logging.Logger.getLogger("java.util.prefs");

    private GuiLauncher() {
    }

    /**
     * @return the window the latest {@link #launch} opens (for test drivers and benchmarks that start through the
     *     command line)
     */
    public static CompletableFuture<MainWindow> lastLaunched() {
        return last;
    }

    /** There is no screen to open a window on. */
    public static final class NoDisplayException extends RuntimeException {
        NoDisplayException(String message) {
            super(message);
        }
    }

    /**
     * Open the window (on the event thread) and return at once.
     *
     * @param options what to load
     * @return completes with the window once it is showing
     * @throws NoDisplayException if there is no display, with the fix
     */
    public static CompletableFuture<MainWindow> launch(GuiOptions options) {
        if (GraphicsEnvironment.isHeadless()) {
            String display = System.getenv("DISPLAY");
            throw new NoDisplayException("no display to open the window on"
                    + (display == null || display.isEmpty() ? " (DISPLAY is not set)"
                            : " (DISPLAY=" + display + ", java.awt.headless="
                    + System.getProperty("java.awt.headless") + ")")
                    + ". Run headless with 'khepera-sim run --arena maze --controller WallFollower', or set DISPLAY to"
                    + " a running X server (for example start 'Xvfb :5 &' and use DISPLAY=:5)");
        }
        PREFS_LOG.setLevel(java.util.logging.Level.WARNING);
        ControllerWindowCloser.install();
        CompletableFuture<MainWindow> shown = last.isDone() ? new CompletableFuture<>() : last;
        last = shown;
        SwingUtilities.invokeLater(() -> {
            try {
                // FlatLaf: a modern look, and proper scaling on HiDPI screens.
                if (!com.formdev.flatlaf.FlatLightLaf.setup()) {
                    LOG.log(System.Logger.Level.DEBUG,
                            "FlatLaf could not be set up; keeping the default look and feel");
                }
                MainWindow w = new MainWindow(options);
                w.frame().setVisible(true);
                shown.complete(w);
            } catch (RuntimeException | Error e) {
                shown.completeExceptionally(e);
            }
        });
        return shown;
    }
}
