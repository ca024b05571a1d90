package org.kheperasim.sim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;

/**
 * The frame every window test shares: a private Xvfb display (the test is skipped without Xvfb,
 * except under {@code CI=true}, where that fails it), a driver class run in a child JVM on it, and
 * the driver's log, checked for a clean exit and the driver's markers.
 */
final class WindowDriverRun {
    private WindowDriverRun() {
    }

    /** @return the target folder the drivers write their logs and screenshots to */
    static Path target() throws IOException {
        return Files.createDirectories(Path.of("target").toAbsolutePath());
    }

    /** Skips the test (or fails it under CI) when there is no Xvfb. @return Xvfb */
    static Path requireXvfb(String what) {
        Path xvfb = GuiEndToEndTest.xvfb();
        if (xvfb == null) {
            if ("true".equals(System.getenv("CI"))) {
                fail("Xvfb is not installed, and CI=true requires " + what + " to run: apt-get install -y xvfb xauth");
            }
            Assumptions.assumeTrue(false, "Xvfb is not installed (apt-get install -y xvfb xauth): the window tests need it");
        }
        return xvfb;
    }

    /**
     * Runs {@code driver}'s main on a fresh display with the arguments {@code target, args...}.
     *
     * @param what    the test, for the skip message
     * @param screen  Xvfb's screen, e.g. {@code 1366x768x24}, or null for the default
     * @param seconds how long the driver may take
     * @param markers lines the driver prints when its checks pass
     * @return the driver's log
     */
    static String run(String what, Class<?> driver, String screen, int seconds, String[] markers, String... args)
            throws IOException, InterruptedException {
        Path xvfb = requireXvfb(what);
        int[] display = new int[1];
        Process x = screen == null ? GuiEndToEndTest.startXvfb(xvfb, display) : GuiEndToEndTest.startXvfb(xvfb, display, screen);
        Path target = target();
        Path log = target.resolve(driver.getSimpleName().replaceAll("([a-z])([A-Z])", "$1-$2").toLowerCase(java.util.Locale.ROOT)
                + ".log");
        String[] all = new String[args.length + 1];
        all[0] = target.toString();
        System.arraycopy(args, 0, all, 1, args.length);
        try {
            Process child = GuiEndToEndTest.childJvm(display[0], driver.getName(), log, all);
            boolean done = child.waitFor(seconds, TimeUnit.SECONDS);
            if (!done) {
                child.destroyForcibly();
            }
            String out = Files.readString(log, StandardCharsets.UTF_8);
            assertTrue(done, "the driver did not finish in " + seconds + " s:\n" + out);
            assertEquals(0, child.exitValue(), out);
            for (String marker : markers) {
                assertTrue(out.contains(marker), "no '" + marker + "' in the driver's log:\n" + out);
            }
            System.out.println(out);
            return out;
        } finally {
            x.destroy();
            x.waitFor(5, TimeUnit.SECONDS);
        }
    }
}
