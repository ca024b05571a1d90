package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The real window under Xvfb: a child JVM (AWT reads DISPLAY when it starts) runs
 * {@link GuiE2EDriver}, which drags a wall across the robot's path with java.awt.Robot, runs
 * Braitenberg and checks the robot turns away. Skipped without Xvfb, except in CI.
 */
class GuiEndToEndTest {

    static Path xvfb() {
        for (String dir : System.getenv().getOrDefault("PATH", "/usr/bin").split(File.pathSeparator)) {
            Path p = Path.of(dir, "Xvfb");
            if (Files.isExecutable(p)) {
                return p;
            }
        }
        return null;
    }

    /** Starts Xvfb on a free display; the caller destroys it. */
    static Process startXvfb(Path xvfb, int[] display) throws IOException, InterruptedException {
        return startXvfb(xvfb, display, "1280x1024x24");
    }

    /** Starts Xvfb with a screen of {@code screen} (e.g. 1366x768x24) on a free display; the caller destroys it. */
    static Process startXvfb(Path xvfb, int[] display, String screen) throws IOException, InterruptedException {
        for (int n = 91; n < 200; n++) {
            if (Files.exists(Path.of("/tmp/.X11-unix/X" + n)) || Files.exists(Path.of("/tmp/.X" + n + "-lock"))) {
                continue;
            }
            Process p = new ProcessBuilder(xvfb.toString(), ":" + n, "-screen", "0", screen, "-nolisten", "tcp")
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            long until = System.nanoTime() + 10_000_000_000L;
            while (System.nanoTime() < until && p.isAlive() && !Files.exists(Path.of("/tmp/.X11-unix/X" + n))) {
                Thread.sleep(50);
            }
            if (p.isAlive() && Files.exists(Path.of("/tmp/.X11-unix/X" + n))) {
                display[0] = n;
                return p;
            }
            p.destroy();
        }
        throw new IllegalStateException("could not start Xvfb on any display :91..:199");
    }

    static Process childJvm(int display, String mainClass, Path log, String... args) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-cp");
        cmd.add(System.getProperty("java.class.path"));
        cmd.add("-Djava.awt.headless=false");
        cmd.add("-Duser.home=" + Path.of("target", "e2e-home").toAbsolutePath());
        cmd.add(mainClass);
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile());
        pb.environment().put("DISPLAY", ":" + display);
        return pb.start();
    }

    @Test
    @Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void drawAWallAcrossTheRobotsPathAndBraitenbergTurnsAway() throws Exception {
        WindowDriverRun.run("the GUI end-to-end test", GuiE2EDriver.class, null, 150, new String[] {"E2E OK"});
        assertTrue(Files.size(WindowDriverRun.target().resolve("e2e-3-turned-away.png")) > 10_000, "a screenshot was saved");
    }
}
