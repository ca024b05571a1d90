package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
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

    /**
     * Starts Xvfb with a screen of {@code screen} (e.g. 1366x768x24) on a display it picks itself
     * ({@code -displayfd}: the server takes the first free number and prints it once it accepts
     * clients, so window tests in parallel test JVMs never share or race for a display); the caller
     * destroys it.
     */
    static Process startXvfb(Path xvfb, int[] display, String screen) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(xvfb.toString(), "-displayfd", "1", "-screen", "0", screen, "-nolisten", "tcp")
                .redirectError(ProcessBuilder.Redirect.DISCARD).start();
        CompletableFuture<String> line = CompletableFuture.supplyAsync(() -> {
            try {
                return new BufferedReader(new InputStreamReader(p.getInputStream(),
                        StandardCharsets.US_ASCII)).readLine();
            } catch (IOException e) {
                return null;
            }
        });
        String n;
        try {
            n = line.get(30, TimeUnit.SECONDS);
        } catch (ExecutionException | TimeoutException e) {
            n = null;
        }
        if (n == null || !n.strip().matches("\\d+")) {
            p.destroyForcibly();
            throw new IllegalStateException("Xvfb did not report a display within 30 s (it printed " + n + ")");
        }
        display[0] = Integer.parseInt(n.strip());
        return p;
    }

    /**
     * @return the home folder of a driver's child JVM: one per driver, so that window tests in
     *     parallel test JVMs never share preferences (RunStatusTest starts from none)
     */
    static Path home(String mainClass) {
        return Path.of("target", "e2e-home", mainClass.substring(mainClass.lastIndexOf('.') + 1));
    }

    static Process childJvm(int display, String mainClass, Path log, String... args) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        // The quick compiler only: a window test's JVM lives seconds, and the optimising compiler spent
        // half of its processor time (7 s of 11 in KeyBindingsDriver); what it checks does not depend on it.
        cmd.add("-XX:TieredStopAtLevel=1");
        cmd.add("-cp");
        cmd.add(System.getProperty("java.class.path"));
        cmd.add("-Djava.awt.headless=false");
        cmd.add("-Duser.home=" + home(mainClass).toAbsolutePath());
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
