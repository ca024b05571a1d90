package org.kheperasim.sim.gui;

import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.check;
import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.onEdt;
import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.onEdtQuiet;
import static org.kheperasim.sim.gui.KeyBindingsDriverSupport.waitFor;

import java.awt.Component;
import java.awt.Container;
import java.awt.Window;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.SwingUtilities;
import org.kheperasim.sim.cli.Main;
import org.kheperasim.sim.run.PacedRunner;

/**
 * Runs in a child JVM under Xvfb (see {@link WebExportTest}): File > Export run as web page, through
 * its file chooser, for the run shown. A live run paused at 20 s gives a page of those 20 s with the
 * window's title and score; a controller that threw gives a page naming the student's line; a
 * replayed trace gives the very page {@code replay --html} writes of it. Arguments: output folder, a
 * trace of a run.
 */
public final class WebExportDriver {
    private static MainWindow w;

    private WebExportDriver() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        Path trace = Path.of(args[1]);
        int code = Main.commandLine().execute("gui", "--arena", "lab", "--controller", "Braitenberg", "--seed", "7");
        check(code == 0, "the gui command returned " + code);
        w = GuiLauncher.lastLaunched().get(20, TimeUnit.SECONDS);
        check(!onEdt(() -> w.action("exportPage").isEnabled()), "nothing to export before a run");

        // A live run, paused at 20 s.
        SwingUtilities.invokeAndWait(() -> {
            w.chooseSpeed(PacedRunner.MAX_SPEED);
            w.action("start").actionPerformed(null);
            w.runner().pauseAt(20_000_000_000L);
        });
        waitFor("the run pauses at 20 s", () -> onEdtQuiet(() -> w.runner().state() == PacedRunner.State.PAUSED
                && w.runner().latest().timeNanos() == 20_000_000_000L));
        Thread.sleep(300);
        Path live = out.resolve("export-live.html");
        Files.deleteIfExists(live);
        export(live);
        String page = Files.readString(live);
        check(page.contains("\"title\":\"Braitenberg in lab, seed 7\""), "the page has the window's run's title");
        // The window's run keeps its trace every 100 ms: the page ends at its last sample, 19.9 s or 20 s.
        check(page.contains("\"endMs\":19900,\"sampleMs\":100,") || page.contains("\"endMs\":20000,\"sampleMs\":100,"),
                "the page replays the 20 s run so far: " + field(page, "endMs"));
        check(page.contains("Made from ") && page.contains("\"source\":\"the window's run, up to 20.0 s\""),
                "the page says what it was made from: " + field(page, "source"));
        String points = lastPoints(page);
        String shown = onEdt(() -> org.kheperasim.sim.task.Score.number(w.score().points()));
        check(points.equals(shown), "the page ends with the window's score " + shown + ", not " + points);
        check(onEdt(() -> w.status().message()).startsWith("Web page saved: "), "the status bar says where: "
                + onEdt(() -> w.status().message()));
        System.out.println("LIVE EXPORT OK: 20 s, score " + points + ", " + Files.size(live) + " bytes");

        // A controller that threw: its page names the student's line.
        SwingUtilities.invokeAndWait(() -> w.action("stop").actionPerformed(null));
        Path src = Files.createDirectories(out.resolve("export-src")).resolve("Thrower.java");
        Files.writeString(src, "import org.kheperasim.api.*;\n\npublic class Thrower extends Controller {\n"
                + "    private final int[] readings = new int[10];\n    private int n;\n\n    @Override\n"
                + "    protected void doWork() {\n        readings[n++] = proximity(IrSensor.FRONT_LEFT);\n"
                + "        setSpeeds(3, 3);\n        sleepMillis(100);\n    }\n}\n");
        check(onEdt(() -> w.compileAndUse(src)), "Thrower compiles:\n" + onEdt(w::consoleText));
        SwingUtilities.invokeAndWait(() -> w.action("start").actionPerformed(null));
        waitFor("Thrower throws and its run ends", () -> onEdtQuiet(() -> w.runner() != null
                && w.runner().state() != PacedRunner.State.RUNNING && w.runner().state() != PacedRunner.State.READY));
        Path threw = out.resolve("export-threw.html");
        Files.deleteIfExists(threw);
        export(threw);
        String failed = Files.readString(threw);
        check(failed.contains("\"status\":\"failed\",\"message\":\"java.lang.ArrayIndexOutOfBoundsException: Index 10 out of"
                + " bounds for length 10 at Thrower.java:9\""), "the page names the failure and the student's line: "
                + field(failed, "failures"));
        System.out.println("FAILURE EXPORT OK");

        // A replay: the page replay --html writes of the same trace, byte for byte.
        check(onEdt(() -> w.openRecording(trace)), "the trace opens:\n" + onEdt(w::consoleText));
        Path replayed = out.resolve("export-replay.html");
        Files.deleteIfExists(replayed);
        export(replayed);
        Path cli = out.resolve("export-replay-cli.html");
        check(Main.commandLine().execute("replay", "--html", cli.toString(), trace.toString()) == 0, "replay --html works");
        check(java.util.Arrays.equals(Files.readAllBytes(replayed), Files.readAllBytes(cli)),
                "the window's page of a replay is replay --html's page of it");
        System.out.println("REPLAY EXPORT OK: " + Files.size(replayed) + " bytes");
        System.exit(0);
    }

    /** File > Export run as web page, through its file chooser. */
    private static void export(Path file) throws Exception {
        check(onEdt(() -> w.action("exportPage").isEnabled()), "Export run as web page is enabled");
        SwingUtilities.invokeLater(() -> w.action("exportPage").actionPerformed(null));
        waitFor("the export shows a file chooser", () -> chooser() != null);
        JFileChooser c = chooser();
        check(onEdt(() -> c.getSelectedFile().getName().equals("run.html")), "it proposes run.html");
        SwingUtilities.invokeAndWait(() -> {
            c.setSelectedFile(file.toFile());
            c.approveSelection();
        });
        waitFor("the page is written", () -> Files.isRegularFile(file));
    }

    /** @return the last score's points in the page's run data */
    private static String lastPoints(String page) {
        Matcher m = Pattern.compile("\\{\"t\":\\d+,\"points\":\"([0-9.]+)\",").matcher(page);
        String last = null;
        while (m.find()) {
            last = m.group(1);
        }
        return String.valueOf(last);
    }

    private static String field(String page, String key) {
        int at = page.indexOf("\"" + key + "\":");
        return at < 0 ? "(none)" : page.substring(at, StrictMath.min(page.length(), at + 300));
    }

    private static JFileChooser chooser() {
        return onEdtQuiet(() -> {
            for (Window win : Window.getWindows()) {
                if (win instanceof JDialog d && d.isShowing()) {
                    JFileChooser f = find(d);
                    if (f != null) {
                        return f;
                    }
                }
            }
            return null;
        });
    }

    private static JFileChooser find(Container root) {
        for (Component c : root.getComponents()) {
            if (c instanceof JFileChooser f) {
                return f;
            }
            if (c instanceof Container k) {
                JFileChooser f = find(k);
                if (f != null) {
                    return f;
                }
            }
        }
        return null;
    }

}
